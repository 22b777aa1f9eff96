-- rose_k_omega.lua started upright at rest (the all-zero body state, as
-- levels/scenarios/rose_paper.lua does) instead of from the static tilt:
-- how much the start decides (docs/FIGURES.md found it decides everything
-- but the rose at the paper's point).
--
--   build/hemiroll sweep levels/sweeps/rose_k_omega_rest.lua --out out/k_omega_rest

return {
  description = "k x Omega around the paper's rose, from rest, 35 s",
  params = { R = 0.04, m_s = 0.1, m_p = 1.0, g = 9.81 },
  drive = { r1 = 0.015, r2 = 0.008, k = 8, Omega = -math.pi / 10 },
  start = "rest",
  duration = 35.0,
  dt = 0.001,
  integrator = "rk4",
  axes = {
    { param = "k", range = { from = 4, to = 16, count = 13 } },
    { param = "Omega", range = { from = -1.0, to = -0.04, count = 13 } },
  },
}
