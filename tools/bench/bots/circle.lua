-- circle: the benchmark's bot. Calls Lua every tick, as every bot does, and
-- does the least a bot can: it reads the mass point once, then moves the
-- proxy on a 1 mm circle at 0.5 Hz around that start point. The motion keeps
-- the physics awake (a proxy held exactly still lets the stepper sleep at a
-- fixed point, which would flatter the figure) and gentle enough that the
-- paper's touchy level runs its full 240 s.

local x, y, z
local w, r = 2 * math.pi * 0.5, 0.001
local cos, sin = math.cos, math.sin

return {
  name = "circle",
  act = function(t, obs)
    if not x then local m = obs.mass; x, y, z = m.x, m.y, m.z end
    return x + r * (cos(w * t) - 1), y + r * sin(w * t), z
  end,
}
