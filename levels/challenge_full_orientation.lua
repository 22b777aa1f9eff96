-- Challenge: the paper's task with the full orientation. Everything as in
-- paper_reaching.lua (Svinin et al. 2009, Sec. 4: masses, R, M3 with alpha
-- = 2, target and tolerances, 4 min), plus psi = 0 within pi/18, the same
-- tolerance the paper gives the other angles (u_co). The paper left psi
-- free because "specifying the complete orientation at the target
-- configuration made the reaching task much more complex" (footnote 3).

local pi = math.pi
local cm = 0.01

return {
  name = "Full orientation",
  description = "The paper's reaching task (4 cm back, 4 cm left, stop upright at rest) AND the " ..
    "hemisphere's turn about the vertical back to zero (psi within 10 degrees). The paper " ..
    "calls this much harder (Sec. 4, footnote 3). Technique: every loop of precession turns " ..
    "psi; plan the loops so the turns cancel.",
  author = "hemiroll",
  difficulty = 5,
  version = "1",

  params = { R = 4 * cm, m_s = 0.1, m_p = 1.0, g = 9.81 },
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },

  task = {
    targets = {
      u_ca = { value = { -4 * cm, -4 * cm }, tol = 0.4 * cm },
      p = { value = { 0, 0 }, tol = 0.4 * cm },
      p_dot = { value = { 0, 0 }, tol = 0.4 * cm },
      omega = { value = { 0, 0, 0 }, tol = 0.01 },
      u_co = { value = { 0, 0 }, tol = pi / 18 },
      psi = { value = 0, tol = pi / 18 },
    },
    hold = 0,
    time_limit = 240,
  },

  score = function(s)
    if not s.success then return 0 end
    return s.time_limit - s.time
  end,
  medals = { bronze = 40, silver = 120, gold = 180 },  -- 200 s, 120 s, 60 s

  scene = { contact_trace = true, plots = { "u_a", "v_a", "psi" }, record_rate = 100 },
}
