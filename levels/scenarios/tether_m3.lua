-- A spring tether: the mass point is coupled with force method M3 (Sec. 3.2,
-- eqs. 43-45) to a proxy held fixed a few millimetres off the face centre,
-- as a hand holding still would. K = R diag(kr, kr, alpha kr) R^T with the
-- paper's preferred gains; the hemisphere settles towards the tilt at which
-- gravity, the spring and the rolling constraint balance.
--
-- The proxy may also be a function of time, evaluated at every integrator
-- stage (base frame, m and m/s):
--   proxy = function(t)
--     local w = 2 * math.pi * 0.5
--     return 0.004 * math.cos(w * t), 0.004 * math.sin(w * t), 0.04,
--            -0.004 * w * math.sin(w * t), 0.004 * w * math.cos(w * t), 0
--   end

local R = 0.04

return {
  description = "M3 spring tether to a fixed proxy 4 mm off the face centre",
  params = { R = R, m_s = 0.1, m_p = 1.0, g = 9.81 },
  drive = {
    kind = "proxy",
    method = "M3",
    kr = 250,     -- [N/m] in-face stiffness (Sec. 4)
    kv = 10,      -- [N s/m] damping (Sec. 4)
    alpha = 2,    -- normal/in-face gain ratio (Sec. 4: 2 preferred)
    proxy = { x = 0.004, y = 0.0, z = R },  -- [m] base frame; the face centre starts at (0, 0, R)
  },
  duration = 3.0,
  dt = 0.001,
}
