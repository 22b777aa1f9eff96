-- random: a seeded random and adversarial bot, for robustness tests. It is
-- not trying to win; it tries to break the engine, which must stay finite,
-- keep every rendered force within the device's limit, and end the trial
-- with a clear reason.
--
-- Behaviour, all from hemiroll.random (seeded by --seed, so a seed replays
-- exactly):
--   - it starts on the mass point (so the coupling engages), then heads for
--     a new random goal every 0.05-0.5 s: mostly (70%) a point within 2 cm
--     of the mass point at up to 5 cm/s, which keeps the trial going; else
--     anywhere in the device's workspace (20%) or far outside it (10%: the
--     device stops at its workspace sphere) at up to 1.5 m/s (the device's
--     velocity guard trips at 2 m/s);
--   - "wild" seeds (seed % 3 == 2) also teleport now and then: one tick from
--     here to a random point, which trips the velocity guard;
--   - "nan" seeds (seed % 5 == 4) return NaN once, at a random time in the
--     first 0.3 s: the trial must end with "bot error: ... nan ...".

local bot = { name = "random" }

local rand = hemiroll.random
local workspace, dt
local wild, nan_time
local px, py, pz          -- current proxy [m]
local gx, gy, gz, speed   -- goal and speed [m/s]
local next_goal = 0.0
local started = false

local function uniform(a, b) return a + (b - a) * rand() end

function bot.init(level, seed)
  workspace = level.workspace
  dt = level.dt
  wild = seed % 3 == 2
  nan_time = (seed % 5 == 4) and uniform(0.05, 0.3) or nil
end

local function pick_goal(obs)
  local kind = rand()
  local m = obs.mass
  if kind < 0.7 then      -- near the mass point, gently
    gx, gy, gz = m.x + uniform(-0.02, 0.02), m.y + uniform(-0.02, 0.02), m.z + uniform(-0.01, 0.01)
    speed = uniform(0.001, 0.05)
    return
  elseif kind < 0.9 then  -- anywhere in (a cube around) the workspace
    local r = workspace.radius
    gx, gy, gz = workspace.x + uniform(-r, r), workspace.y + uniform(-r, r), workspace.z + uniform(-r, r)
  else                    -- far outside: the device must stop at its sphere
    gx, gy, gz = uniform(-1e3, 1e3), uniform(-1e3, 1e3), uniform(-1e3, 1e3)
  end
  speed = uniform(0.01, 1.5)
end

function bot.act(t, obs)
  if not started then
    px, py, pz = obs.mass.x, obs.mass.y, obs.mass.z
    started = true
    next_goal = 0.2  -- stay on the mass point until the coupling has engaged
    gx, gy, gz, speed = px, py, pz, 0.0
  end
  if nan_time and t >= nan_time then
    return 0 / 0, py, pz
  end
  if t >= next_goal then
    pick_goal(obs)
    next_goal = t + uniform(0.05, 0.5)
    if wild and rand() < 0.2 then
      local r = workspace.radius
      px, py, pz = workspace.x + uniform(-r, r), workspace.y + uniform(-r, r), workspace.z + uniform(-r, r)
    end
  end
  local dx, dy, dz = gx - px, gy - py, gz - pz
  local d = math.sqrt(dx * dx + dy * dy + dz * dz)
  local step = speed * dt
  if d > step then
    px, py, pz = px + dx / d * step, py + dy / d * step, pz + dz / d * step
  else
    px, py, pz = gx, gy, gz
  end
  return px, py, pz
end

return bot
