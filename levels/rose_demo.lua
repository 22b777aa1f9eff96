-- The Sec. 5 rose demonstration as a scene to watch (Svinin et al. 2009,
-- Sec. 5, eqs. 49-50): a bot moves the proxy along the double-pendulum
-- "rose" curve (r1 = 1.5 cm, r2 = 0.8 cm, k = 8, Omega = -pi/10 rad/s) and
-- the M3 coupling pulls the mass point after it; the contact point traces
-- the helical path of Fig. 10. The bot is scripts/bots/rose.lua (module
-- "bots.rose"), written with the bots; this file only sets the scene.
-- Masses and R are Sec. 4's (the paper's simulation uses them), 35 s as in
-- the paper's run. Nothing to solve: the level is watch-only (no targets)
-- and ends "watched to the end" at 35 s, or early if the hemisphere tips.
-- Differs from the paper in one respect: the paper prescribes the mass
-- point exactly (levels/scenarios/rose_paper.lua does that with `hemiroll
-- sim`); here it follows a proxy through the spring, as a player's would.

return {
  name = "The rose (watch)",
  description = "Watch the paper's human-inspired actuation (Sec. 5): the mass point draws a " ..
    "nine-leaf rose on the face and the hemisphere precesses along a helix. Nothing to do: " ..
    "a bot plays it.",
  author = "hemiroll, after Svinin et al. (2009), Sec. 5",
  difficulty = 1,
  version = "1",

  params = { R = 0.04, m_s = 0.1, m_p = 1.0, g = 9.81 },
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },

  task = { time_limit = 35 },  -- no targets: watch-only
  demo_bot = "bots.rose",

  scene = { contact_trace = true, plots = { "x_p", "y_p", "u_a", "v_a" }, record_rate = 100 },
}
