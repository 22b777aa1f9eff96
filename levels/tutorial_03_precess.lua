-- Tutorial 3: precess. Keep the hemisphere tilted and carry the mass point
-- around the centre: the tilt direction turns and the contact point runs
-- round a small circle. Rolling round a closed loop does not bring the
-- hemisphere back as it was: it comes back turned about the vertical (psi).
-- That turn is the precession the paper's subjects used (Sec. 4.2).
-- `hemiroll sim`, same masses: the mass point circled at 1.8 cm, 8 s per
-- turn, counter-clockwise, runs the contact round a 3.8 mm circle and turns
-- psi by about -0.11 rad per turn. A proxy eased out to 1.8 cm, circled once
-- (t = 2 .. 10.5 s) and eased back to the centre by 12 s passes the gates at
-- 0.7, 3.5, 5.5 and 7.5 s and meets the last stage at 15.4 s (psi -0.125).

local r = 0.0035  -- gate radius on the plane [m]
local gate = 0.0015
local last_stage = nil  -- level state lives in locals of this file

return {
  name = "03 Precess",
  description = "Stir: move the mouse in small quick circles, about 6 mm across and a turn every two " ..
    "seconds, anticlockwise, round the contact point (where the hemisphere touches the floor). " ..
    "The hemisphere leans and turns with your stir. Aim the circles a little off the contact point " ..
    "and the contact point wanders through four gates on a small circle, right, ahead, left and " ..
    "behind (the green arrow points to the next). Last, it must stand up turned a little about the " ..
    "vertical: while the HUD says to turn it further, keep stirring on the spot, with no aim (an " ..
    "anticlockwise stir turns it clockwise); once the heading is well inside its band, let the " ..
    "circles die away and hold still.",
  author = "hemiroll",
  difficulty = 2,
  version = "1",

  params = { R = 0.04, m_s = 1.0, m_p = 0.2, g = 9.81 },
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },

  task = {
    stages = {
      { name = "gate +x", targets = { u_ca = { value = { r, 0 }, tol = gate } } },
      { name = "gate +y", targets = { u_ca = { value = { 0, r }, tol = gate } } },
      { name = "gate -x", targets = { u_ca = { value = { -r, 0 }, tol = gate } } },
      { name = "gate -y", targets = { u_ca = { value = { 0, -r }, tol = gate } } },
      { name = "upright, turned",
        targets = {
          u_co = { value = { 0, 0 }, tol = 0.03 },
          omega_norm = { value = 0, tol = 0.03 },
          psi = { value = -0.15, tol = 0.1 },
        },
        hold = 1.0 },
    },
    time_limit = 120,
  },

  score = function(s)
    if not s.success then return 100 * s.stages_passed end
    return math.floor(500 + 500 * (1 - s.time / s.time_limit))
  end,
  medals = { bronze = 500, silver = 700, gold = 850 },

  scene = { contact_trace = true, plots = { "u_a", "v_a", "psi" }, record_rate = 100 },
  callbacks = {
    rate = 10,
    on_start = function(state)
      last_stage = nil
      hemiroll.message("Stir small quick circles round the contact point, a turn every 2 s", 5)
    end,
    on_update = function(state)
      if state.stage ~= last_stage then
        if last_stage then hemiroll.message("Gate " .. last_stage .. " passed", 2) end
        last_stage = state.stage
      end
    end,
  },
}
