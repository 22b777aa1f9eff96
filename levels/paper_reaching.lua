-- The paper's experiment, exactly: Svinin et al., "Dynamic Model, Haptic
-- Solution, and Human-Inspired Motion Planning for Rolling-Based
-- Manipulation", J. Comput. Inf. Sci. Eng. 9 (2009), Sec. 4.
--
-- Where every number comes from (section and paragraph of the paper):
--   g = 9.81 m/s^2, m_p = 1 kg, m_s = 0.1 kg, R = 4 cm ....... Sec. 4, para. 1
--   start: all state variables of eq. (22) zero, at rest ...... Sec. 4, para. 2
--   target: u_ca = {-4, -4} cm; p, p-dot, omega, u_co zero;
--           psi not specified (free) ........................... Sec. 4, para. 3 (and footnote 3)
--   tolerances: omega +-0.01 rad/s, u_ca +-0.4 cm, u_co +-pi/18
--           rad, p +-0.4 cm, p-dot +-0.4 cm/s, per component ... Sec. 4, para. 4
--   time limit: 4 min ........................................ Sec. 4, para. 4
--   force: M3, k_rx = k_ry = 250 N/m, k_vx = k_vy = 10 N s/m,
--          alpha = k_rz/k_rx = k_vz/k_vx = 2 .................. Sec. 4.1, paras. 3 and 4; Sec. 4.2
--   hold: the paper states none (the trial succeeds when the state is
--         inside every tolerance), so hold = 0 ................... Sec. 4, para. 4
-- Medal thresholds (ours, from the paper's reported times): gold = the
-- "within 40 s" some subjects reached (Sec. 4.1, para. 4), silver = the
-- fastest recorded trial, 46 s, bronze = the slowest, 170 s (Sec. 4.2).
-- The score is the time left: 240 s - trial time, 0 on failure.
-- Everything is SI: metres, seconds, radians, kilograms, newtons.

local pi = math.pi
local cm = 0.01

return {
  name = "The paper's reaching task",
  description = "THE PAPER'S EXPERIMENT (Svinin et al. 2009, Sec. 4), unchanged: move the contact " ..
    "point 4 cm back and 4 cm left and stop there, upright and at rest, with the mass point " ..
    "on top, within the paper's tolerances and 4 minutes. Technique (Sec. 4.2): tilt, then " ..
    "circle the mass point so the hemisphere precesses along a helix towards the target, " ..
    "then calm it down on the spot (tutorials 4 to 6 teach it: the swirl, then the brake).",
  author = "hemiroll, after Svinin, Goncharenko, Luo and Hosoe (2009)",
  difficulty = 5,
  version = "1",

  params = { R = 4 * cm, m_s = 0.1, m_p = 1.0, g = 9.81 },
  -- initial omitted: every state variable is 0 (Sec. 4, para. 2)
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },

  task = {
    targets = {
      u_ca = { value = { -4 * cm, -4 * cm }, tol = 0.4 * cm },
      p = { value = { 0, 0 }, tol = 0.4 * cm },
      p_dot = { value = { 0, 0 }, tol = 0.4 * cm },   -- 0.4 cm/s
      omega = { value = { 0, 0, 0 }, tol = 0.01 },
      u_co = { value = { 0, 0 }, tol = pi / 18 },
      -- psi: not specified in the paper's target (footnote 3)
    },
    hold = 0,
    time_limit = 240,
  },

  score = function(s)
    if not s.success then return 0 end
    return s.time_limit - s.time
  end,
  medals = { bronze = 240 - 170, silver = 240 - 46, gold = 240 - 40 },

  scene = {
    contact_trace = true, plots = { "u_a", "v_a" }, record_rate = 100,  -- Fig. 5 shows x of the contact
    -- Scenery only (nothing collides with it): a flag past the target, far
    -- enough (5 cm, more than R) that the hemisphere at the target clears it,
    -- and two cones behind the start.
    props = {
      { mesh = "meshes/flag.obj", position = { -0.075, -0.075, 0 }, size = 0.015, colour = { 0.9, 0.25, 0.2 } },
      { mesh = "meshes/cone.gltf", position = { 0.065, 0.02, 0 }, size = 0.008 },
      { mesh = "meshes/cone.gltf", position = { 0.02, 0.065, 0 }, size = 0.008 },
    },
  },
}
