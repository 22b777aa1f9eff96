-- Challenge: a forbidden zone. The target lies 3.5 mm along -x, but a
-- circular pit sits on the straight way there. A straight roll towards -x
-- falls in; the way round is half a loop of precession (tutorial 3): out
-- towards +x or +y first, round the pit, and hold at the far side.
-- Gentle masses as in the tutorials, so the hold only needs the mass point
-- kept off centre (about 1.7 cm towards -x), not a full stop upright.

return {
  name = "Forbidden zone",
  description = "Bring the contact point to 3.5 mm along -x and hold it there for 1 s, without the " ..
    "contact point ever entering the pit (a 1.2 mm circle at -1.8 mm). Technique: swing round " ..
    "it: tilt towards +y first, then carry the mass point round to -x.",
  author = "hemiroll",
  difficulty = 2,
  version = "1",

  params = { R = 0.04, m_s = 1.0, m_p = 0.2, g = 9.81 },
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },

  task = {
    targets = {
      u_ca = { value = { -0.0035, 0 }, tol = 0.0012 },
      omega_norm = { value = 0, tol = 0.05 },
    },
    hold = 1.0,
    time_limit = 90,
    forbidden = {
      { name = "the pit", shape = "circle", center = { -0.0018, 0 }, radius = 0.0012 },
    },
  },

  score = function(s)
    if not s.success then return 0 end
    return math.floor(1000 * (1 - s.time / s.time_limit))
  end,
  medals = { bronze = 300, silver = 600, gold = 800 },

  scene = { contact_trace = true, plots = { "u_a", "v_a" }, record_rate = 100 },
  callbacks = {
    rate = 10,
    on_start = function(state) hemiroll.message("Mind the pit: go round it", 4) end,
    on_fail = function(state, reason) hemiroll.message(reason, 4) end,
  },
}
