-- tutorial_solver: completes the first tutorial levels (01 tilt and return,
-- 02 roll a short distance) by feedback on the observation alone. It reads
-- the current stage's targets from obs.target, so it follows any stage
-- sequence made of the same kinds of targets.
--
-- Control law (derived for straight rolls, tuned in simulation):
--   The proxy is held at a point (X, Y) in the scene, at the mass point's
--   height (so it pushes only sideways). For a proxy held still, the
--   hemisphere settles in an equilibrium where the mass point sits a little
--   off the face centre and the body is tilted: holding X = 1.5 cm gives
--   u_o ~ -0.087 rad with the tutorial masses. In a straight roll the
--   contact point and the tilt are tied, u_a = -R u_o and v_a = R v_o, so
--   one knob per direction sets either.
--   The bot moves (X, Y) slowly in the direction that reduces the error
--   (integral action, so the equilibrium itself is found without a model):
--     X' = ko (u_o - u_o*)      when u_o is a target (more +X tilts to -u_o)
--     X' = ka (u_a* - u_a)      when u_a is a target
--     Y' = ko (v_o* - v_o)      when v_o is a target (more +Y tilts to +v_o)
--     Y' = ka (v_a* - v_a)      when v_a is a target
--   with the speed limited to vmax. The gains make the integral loop about
--   three times slower than the hemisphere settles (~1.5 s), so the loop does
--   not ring: ko = 0.05 m/(rad s), ka = 1.5 1/s, vmax = 1 cm/s. An upright,
--   centred, still target (u_co = 0, p = 0, omega = 0) is the equilibrium of
--   X = contact point, so the same law returns the hemisphere upright.
-- Limits: straight rolls only (psi stays near 0); a target that needs
-- precession (moving the contact point while ending upright) is beyond it.

local bot = { name = "tutorial_solver" }

local ko, ka, vmax = 0.05, 1.5, 0.01
local dt = 0.001
local X, Y

function bot.init(level, seed)
  dt = level.dt
end

local function clamp(v, limit)
  if v > limit then return limit elseif v < -limit then return -limit end
  return v
end

function bot.act(t, obs)
  local m = obs.mass
  if not X then X, Y = m.x, m.y end
  local s, want = obs.state, obs.target
  local vx, vy = 0, 0
  if want.u_o then vx = ko * (s.u_o - want.u_o) elseif want.u_a then vx = ka * (want.u_a - s.u_a) end
  if want.v_o then vy = ko * (want.v_o - s.v_o) elseif want.v_a then vy = ka * (want.v_a - s.v_a) end
  X = X + clamp(vx, vmax) * dt
  Y = Y + clamp(vy, vmax) * dt
  return X, Y, m.z
end

return bot
