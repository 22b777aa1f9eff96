-- The paper's k = 8, Omega = -pi/10 with the pendulum's links and the
-- masses varied: r1 and r2 over the human data's range (Sec. 4.2: leaf
-- radius 0.4-1.0 cm, outer radius 1.2-2.4 cm) and beyond, the mass point
-- and the hemisphere by factors of 2 around the paper's 1 kg and 0.1 kg.
-- From the static tilt for p(0), computed for each point's masses and links.
--
-- The masses are written out (not a log range) so that m_p / m_s is the
-- same, to the bit, along each diagonal of the m_p x m_s map: the motion
-- depends on the masses only through their ratio (docs/SWEEP.md).
--
--   build/hemiroll sweep levels/sweeps/rose_links_masses.lua --out out/links_masses

return {
  description = "r1 x r2 x m_p x m_s at the paper's k and Omega, from the static tilt for p(0), 35 s",
  params = { R = 0.04, m_s = 0.1, m_p = 1.0, g = 9.81 },
  drive = { r1 = 0.015, r2 = 0.008, k = 8, Omega = -math.pi / 10 },
  start = "equilibrium",
  duration = 35.0,
  dt = 0.001,
  integrator = "rk4",
  axes = {
    { param = "r1", range = { from = 0.005, to = 0.020, count = 7 } },    -- [m]
    { param = "r2", values = { 0.003, 0.005, 0.008, 0.010, 0.012 } },      -- [m]
    { param = "m_p", values = { 0.125, 0.25, 0.5, 1.0, 2.0 }, log = true },  -- [kg], maps in log10
    { param = "m_s", values = { 0.025, 0.05, 0.1, 0.2, 0.4 }, log = true },  -- [kg]
  },
}
