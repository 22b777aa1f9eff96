-- The Sec. 5 rose drive of rose_paper.lua, started as the paper says it
-- was: "from the equilibrium state corresponding to p(0)" (Svinin et al.
-- 2009, Sec. 5), instead of from the upright all-zero state.
--
-- With the mass point held at d = r1 + r2 = 2.3 cm on the face's x axis,
-- the hemisphere rests tilted by theta where
--   m_p cos(theta) (d - R sin(theta)) = (3R/8) m_s sin(theta)
-- (physics-notes.md): theta = 0.58271 rad (33.39 degrees) for the paper's
-- masses. In the contact angles that tilt is u_o = -theta (v_o = psi = 0):
-- with Omega = 0 this state stays at rest (checked with `hemiroll sim`:
-- |w| = 1.4e-4 rad/s after 0.5 s, against 12 rad/s for u_o = +theta;
-- tests/game/FiguresCommandTest.cpp).
-- The mass point still starts moving with the curve's velocity, so the
-- start is an equilibrium of position, not of motion.
--
-- docs/FIGURES.md compares the two starts (`hemiroll figures --scenario`).

local pi = math.pi

return {
  description = "Svinin et al. Sec. 5: rose-curve actuation from the static tilt for p(0), 35 s",
  params = { R = 0.04, m_s = 0.1, m_p = 1.0, g = 9.81 },  -- Sec. 4
  initial = { u_o = -0.58271 },                          -- [rad] the static tilt for p(0), see above
  drive = { kind = "rose", r1 = 0.015, r2 = 0.008, k = 8, Omega = -pi / 10 },
  duration = 35.0,
  dt = 0.001,
  integrator = "rk4",
}
