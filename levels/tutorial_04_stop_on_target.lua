-- Tutorial 4: stop on target. The paper's task (paper_reaching.lua) in
-- miniature, with gentler masses (m_s = 0.5 kg, m_p = 0.5 kg) and tolerances
-- about twice the paper's. The target is not reachable by a straight roll:
-- with the mass point within 8 mm of the centre the hemisphere cannot stay
-- tilted enough to hold the contact point 1 cm away, so the contact point
-- must be walked there by precession (tutorial 3) and the hemisphere
-- brought upright on the spot.

local pi = math.pi

return {
  name = "04 Stop on target",
  description = "Bring the hemisphere 1 cm to the right, onto the green target square, and stop there nearly " ..
    "upright and at rest, mass point near the middle. Leaning only tilts it: to travel, swirl. " ..
    "Circle the mouse anticlockwise, a turn every two seconds, round the spot the hemisphere would " ..
    "stand on if it were rolled upright (the contact point moved back against the lean, about " ..
    "0.7 mm per degree of tilt), in circles as big as keep the tilt gauge at about 10 degrees. Put " ..
    "the circles' middle a few millimetres off that spot, a quarter turn from the way to go, to the " ..
    "side the hemisphere turns: it drifts the way to go. On the target let the circles die away " ..
    "over a second or two, then hold still over the spot and nudge gently. Still turning? Swirl a " ..
    "second the way it turns, then let that die away too. Stuck? {key:hint} shows the ring to trace. " ..
    "The paper's task, gentler.",
  author = "hemiroll",
  difficulty = 3,
  version = "1",

  params = { R = 0.04, m_s = 0.5, m_p = 0.5, g = 9.81 },
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },

  task = {
    targets = {
      u_ca = { value = { 0.01, 0 }, tol = 0.004 },
      p = { value = { 0, 0 }, tol = 0.008 },
      p_dot = { value = { 0, 0 }, tol = 0.01 },
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
