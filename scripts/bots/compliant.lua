-- A hand that only yields to the device, written in Lua with lib/arm.lua:
-- the Lua twin of `--bot passive-hand`, and the start of a Lua bot that
-- feels guidance (a pose-commanded bot puts the proxy where it likes, and
-- guidance moves nothing of it). Give hand:step an intent to pull towards.
local arm = require("lib.arm")

local hand
local bot = { name = "compliant" }

function bot.init(level, seed)
  hand = arm.new{ dt = level.dt }
end

function bot.act(t, obs)
  return hand:step(obs)
end

return bot
