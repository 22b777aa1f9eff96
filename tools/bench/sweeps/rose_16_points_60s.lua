-- The sweep of issue 32's profile (docs/PERFORMANCE.md): 16 points of 60 s
-- around the paper's rose, as a user runs it (`hemiroll sweep --threads 1
-- --maps none`). Small enough to profile in a few seconds, long enough that
-- the per-point analysis (60 s at 100 Hz) weighs as it does in real sweeps.
return {
  description = "benchmark: k x Omega around the paper's rose, 4 x 4 points, 60 s",
  params = { R = 0.04, m_s = 0.1, m_p = 1.0, g = 9.81 },
  drive = { r1 = 0.015, r2 = 0.008, k = 8, Omega = -math.pi / 10 },
  start = "equilibrium",
  duration = 60.0,
  dt = 0.001,
  integrator = "rk4",
  axes = {
    { param = "k", values = { 6, 8, 10, 12 } },
    { param = "Omega", values = { -0.6, -0.4, -math.pi / 10, -0.2 } },
  },
}
