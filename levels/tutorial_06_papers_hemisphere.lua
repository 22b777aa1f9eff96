-- Tutorial 06: the step from the tutorials' tame bodies to the paper's task.
-- The paper's hemisphere and coupling (a 0.1 kg shell under a 1 kg mass
-- point, M3 at k_r 250 N/m, k_v 10 N s/m, alpha 2: Sec. 4 and 4.1), a
-- target 2 cm off, and tutorial 04's bands at the end, looser than the
-- paper's (omega 0.05 rad/s against 0.01, p 8 mm against 4, p-dot 1 cm/s
-- against 4 mm/s, u_co pi/9 against pi/18), held for half a second.
-- The technique is tutorial 05's; what is new is the body: the heavy mass
-- point on top makes every lean bigger and every spin last. Once this one
-- is won, the paper's own task (paper_reaching.lua) asks for the same with
-- the paper's bands.

local pi = math.pi
local cm = 0.01

return {
  name = "06 The paper's hemisphere",
  description = "The paper's own hemisphere: a light shell under a heavy mass point, livelier than " ..
    "the tutorials'. Bring it 2 cm to the right, onto the target, and stop there nearly upright " ..
    "and at rest. Swirl as in tutorials 4 and 5, circles that keep the tilt gauge at about 10 " ..
    "degrees: here that is a small swirl, about 5 mm, and a bigger one throws the mass point off. " ..
    "On the target let the circles die away and hold still over the spot; still turning, swirl a " ..
    "second the way it turns and let that die away. Stuck? {key:hint} shows the ring to trace. " ..
    "Next: the paper's task.",
  author = "hemiroll",
  difficulty = 4,
  version = "1",

  params = { R = 4 * cm, m_s = 0.1, m_p = 1.0, g = 9.81 },
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },

  task = {
    targets = {
      u_ca = { value = { 2 * cm, 0 }, tol = 0.4 * cm },
      p = { value = { 0, 0 }, tol = 0.8 * cm },
      p_dot = { value = { 0, 0 }, tol = 1 * cm },
      omega = { value = { 0, 0, 0 }, tol = 0.05 },
      u_co = { value = { 0, 0 }, tol = pi / 9 },
    },
    hold = 0.5,
    time_limit = 240,
  },

  score = function(s)
    if not s.success then return 0 end
    return math.floor(1000 * (1 - s.time / s.time_limit))
  end,
  medals = { bronze = 250, silver = 600, gold = 800 },  -- 180 s, 96 s, 48 s

  scene = { contact_trace = true, plots = { "u_a", "v_a" }, record_rate = 100 },
}
