-- The paper's open question (Svinin et al. 2009, Sec. 5): for which k and
-- Omega does the rose drive give a nearly constant precession speed and a
-- contact trace curved like the human data? k x Omega around the paper's
-- k = 8, Omega = -pi/10, with its links (r1 = 1.5 cm, r2 = 0.8 cm) and
-- masses (m_p = 1 kg, m_s = 0.1 kg, R = 4 cm), from the static tilt for
-- p(0) as the paper started (docs/SWEEP.md shows the maps).
--
--   build/hemiroll sweep levels/sweeps/rose_k_omega.lua --out out/k_omega

return {
  description = "k x Omega around the paper's rose, from the static tilt for p(0), 35 s",
  params = { R = 0.04, m_s = 0.1, m_p = 1.0, g = 9.81 },      -- Sec. 4
  drive = { r1 = 0.015, r2 = 0.008, k = 8, Omega = -math.pi / 10 },
  start = "equilibrium",                                       -- computed per point
  duration = 35.0,                                             -- [s], the paper's interval
  dt = 0.001,                                                  -- [s], the paper's RK4 step
  integrator = "rk4",
  axes = {
    { param = "k", range = { from = 4, to = 16, count = 13 } },           -- 5 to 17 leaves
    { param = "Omega", range = { from = -1.0, to = -0.04, count = 13 } },  -- [rad/s], -pi/10 lies in between
  },
}
