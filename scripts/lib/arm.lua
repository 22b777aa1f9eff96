-- A compliant arm for Lua bots (docs/RUN.md "Feeling the device"): the
-- built-in passive hand's mechanics (game/trial/PassiveHandBot), so that a
-- Lua bot can hold the device as a hand does and feel what it renders
-- (coupling and guidance) instead of putting the proxy where it likes:
--
--   m a = F_device - k (x - a) - b v
--
-- where a is the arm's aim: the bot's intent when it gives one, else where
-- the hand has been lately (da/dt = (x - a) / settle_time), which steadies
-- the hand against quick pushes and gives way to a push that lasts.
-- Semi-implicit Euler at the trial's tick, the same operations in the same
-- order as the built-in hand, so a bot that gives no intent plays as
-- `--bot passive-hand` does.
--
--   local arm = require("lib.arm")
--   local hand = arm.new()                      -- or arm.new{ mass = 0.3, stiffness = 150, ... }
--   function bot.act(t, obs) return hand:step(obs) end                 -- yields only
--   function bot.act(t, obs) return hand:step(obs, gx, gy, gz) end     -- pulled towards an intent
--
-- Units SI: kg, N/m, N s/m, s. No table is made per tick.

local arm = {}
arm.__index = arm

-- The passive hand's defaults (PassiveHandDef).
function arm.new(def)
  def = def or {}
  return setmetatable({
    mass = def.mass or 0.3,
    stiffness = def.stiffness or 150,
    damping = def.damping or 10,
    settle_time = def.settle_time or 1,
    dt = def.dt or 0.001,   -- the trial's tick: a paused loop's step is clamped to 10 of them
    holding = false,
    x = 0, y = 0, z = 0, vx = 0, vy = 0, vz = 0, ax = 0, ay = 0, az = 0, last = 0,
  }, arm)
end

local function clamp(v, lo, hi)
  if v < lo then return lo end
  if v > hi then return hi end
  return v
end

-- One tick: returns the proxy's position and velocity (six numbers, what
-- act returns). With an intent (gx, gy, gz) the arm pulls towards it;
-- without, towards where the hand has been.
function arm:step(obs, gx, gy, gz)
  local m = obs.mass
  if not self.holding then  -- takes hold where the mass point is, at rest
    self.holding = true
    self.x, self.y, self.z = m.x, m.y, m.z
    self.ax, self.ay, self.az = m.x, m.y, m.z
    self.last = obs.time
  else
    local dt = clamp(obs.time - self.last, 0, 10 * self.dt)
    self.last = obs.time
    local f = obs.device_force
    local k, b, mass, tau = self.stiffness, self.damping, self.mass, self.settle_time
    if gx then self.ax, self.ay, self.az = gx, gy, gz end
    local arm_x = -k * (self.x - self.ax) - b * self.vx
    self.vx = self.vx + dt * (f.x + arm_x) / mass
    self.x = self.x + dt * self.vx
    if not gx then self.ax = self.ax + dt * (self.x - self.ax) / tau end
    local arm_y = -k * (self.y - self.ay) - b * self.vy
    self.vy = self.vy + dt * (f.y + arm_y) / mass
    self.y = self.y + dt * self.vy
    if not gx then self.ay = self.ay + dt * (self.y - self.ay) / tau end
    local arm_z = -k * (self.z - self.az) - b * self.vz
    self.vz = self.vz + dt * (f.z + arm_z) / mass
    self.z = self.z + dt * self.vz
    if not gx then self.az = self.az + dt * (self.z - self.az) / tau end
  end
  return self.x, self.y, self.z, self.vx, self.vy, self.vz
end

return arm
