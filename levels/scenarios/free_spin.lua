-- Free motion: no external force, the mass point free on the frictionless
-- face. The hemisphere spins upright about the vertical with the mass point at
-- the face centre: a steady motion, but not a stable one. A small rocking
-- nudge (w_x) tilts the face, the point slides downhill, and within about a
-- second it reaches the rim of the face: the run ends with a `left_face`
-- event, which is a result, not an error (the CSV's last row is the state at
-- the located event time). Without a hand holding the point, nothing stops it.
--
-- Total energy T + V is conserved by the exact model (physics-notes.md,
-- "Checks that hold exactly"), so the energy column shows the integrator's
-- drift alone. Set w_x = 0 to see the steady spin carry on to the end.

return {
  description = "free motion: upright spin, point at the centre, small nudge",
  params = { R = 0.04, m_s = 0.1, m_p = 1.0, g = 9.81 },  -- the paper's values
  initial = {
    w_z = 6.0,   -- [rad/s] spin about the vertical
    w_x = 0.01,  -- [rad/s] a small rocking nudge
  },
  drive = { kind = "free" },
  duration = 2.0,  -- [s]
  dt = 0.001,      -- [s]
}
