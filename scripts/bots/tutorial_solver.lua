-- tutorial_solver: completes the first tutorial levels (01 tilt and return,
-- 02 roll a short distance, 03 precess; also the slalom and the time trial)
-- by feedback on the observation alone. It reads the current stage's
-- targets from obs.target, so it follows any stage sequence made of the
-- same kinds of targets.
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
--     X' = ka (u_a* - u_a)      when u_a is a target (and u_o, if one, is
--                               inside its band)
--     X' = ko (u_o - u_o*)      else, when u_o is a target (more +X tilts to -u_o)
--     Y' = ka (v_a* - v_a)      likewise for y
--     Y' = ko (v_o* - v_o)      (more +Y tilts to +v_o)
--   with the speed limited to vmax. The gains make the integral loop about
--   three times slower than the hemisphere settles (~1.5 s), so the loop does
--   not ring: ko = 0.05 m/(rad s), ka = 1.5 1/s, vmax = 1 cm/s. An upright,
--   centred, still target (u_co = 0, p = 0, omega = 0) is the equilibrium of
--   X = contact point, so the same law returns the hemisphere upright.
-- Precession, for a psi target: rolling round a closed loop turns the
--   hemisphere about the vertical (the paper's Sec. 4.2 precession). While
--   psi is outside half its band the proxy circles (X, Y) at 1.8 cm, 8 s per
--   turn (counter-clockwise turns psi negative; levels/tutorial_03 measured
--   -0.11 rad per turn), eased in and out over 1.5 s; then the law above
--   brings the hemisphere upright again. Found to pass tutorial 03 first
--   time with the level's own numbers.
-- Limits: it moves the contact point only by straight rolls, so a target
-- that needs the contact far away with the hemisphere upright (tutorial 04,
-- the paper's task: spiral there by precessing) is beyond it.

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

-- Precession (a psi target): circle the proxy round (X, Y) at radius rp,
-- one turn per period, eased in and out over ease seconds; counter-clockwise
-- turns psi negative. Stops easing out once psi is inside half its band.
local rp, period, ease = 0.018, 8.0, 1.5
local phase, radius, circling = 0.0, 0.0, false

local function precess(obs, want, tol)
  local err = obs.state.psi - want
  if circling and math.abs(err) < 0.5 * tol then circling = false end
  if not circling and radius == 0 and math.abs(err) >= 0.5 * tol then circling = true end
  local dir = err > 0 and 1 or -1
  radius = math.max(0, math.min(rp, radius + (circling and 1 or -1) * rp / ease * dt))
  phase = phase + dir * 2 * math.pi / period * dt
  return radius * math.cos(phase), radius * math.sin(phase)
end

function bot.act(t, obs)
  local m = obs.mass
  if not X then X, Y = m.x, m.y end
  local s, want = obs.state, obs.target
  if want.psi and (circling or radius > 0 or math.abs(s.psi - want.psi) >= 0.5 * obs.tolerance.psi) then
    local cx, cy = precess(obs, want.psi, obs.tolerance.psi)
    return X + cx, Y + cy, m.z
  end
  -- Per direction: the contact point when it is a target and the tilt (if
  -- also a target) is inside its band; else the tilt.
  local tol = obs.tolerance
  local vx, vy = 0, 0
  if want.u_a and not (want.u_o and math.abs(s.u_o - want.u_o) > tol.u_o) then
    vx = ka * (want.u_a - s.u_a)
  elseif want.u_o then
    vx = ko * (s.u_o - want.u_o)
  end
  if want.v_a and not (want.v_o and math.abs(s.v_o - want.v_o) > tol.v_o) then
    vy = ka * (want.v_a - s.v_a)
  elseif want.v_o then
    vy = ko * (want.v_o - s.v_o)
  end
  X = X + clamp(vx, vmax) * dt
  Y = Y + clamp(vy, vmax) * dt
  return X, Y, m.z
end

return bot
