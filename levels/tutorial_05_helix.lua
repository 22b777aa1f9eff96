-- Tutorial 5: the helix. The paper's technique for going far (Sec. 4.2):
-- a straight push only leans the hemisphere (tutorial 2 gets 4 mm), so its
-- subjects leaned it and circled the mass point, and the contact point
-- went round in loops that carried it along a curve, the helix of the
-- contact trace. The floor shows an example: a dashed path of three loops
-- to a target 2 cm away (a trochoid, the loops' radius that of tutorial 3's
-- circle), with a gate after each loop. The masses are tutorial 4's.
-- Checked with `hemiroll run levels/tutorial_05_helix.lua --bot autopilot`.

local pi = math.pi
local distance, loops, r = 0.02, 3, 0.0035  -- [m], [-], [m]

-- x = s + r sin(theta), y = r (1 - cos(theta)), s growing evenly to
-- `distance` over `loops` turns: loops wherever r > distance / (2 pi loops).
local path = {}
local steps = 60 * loops
for i = 0, steps do
  local theta = 2 * pi * loops * i / steps
  local s = distance * i / steps
  path[#path + 1] = { s + r * math.sin(theta), r * (1 - math.cos(theta)) }
end

local gate = 0.003
local last_stage = nil

return {
  name = "05 The helix",
  description = "Go 2 cm to the right, further than a lean can take you, the way the paper's " ..
    "players did: swirl (tutorial 4), anticlockwise circles a turn every two seconds round the " ..
    "spot it would stand on upright, as big as keep the tilt gauge at about 10 degrees, their " ..
    "middle a few millimetres off that spot, a quarter turn from the way to go, to the side it " ..
    "turns. The contact point loops along a helix: the dashed blue path on the floor shows three " ..
    "loops, with a gate after each (a lean alone reaches the first two, not the last). At the " ..
    "target let the circles die away, then hold still over the spot; still turning, swirl a second " ..
    "the way it turns and let that die away. Stuck? {key:hint} shows the ring to trace.",
  author = "hemiroll",
  difficulty = 3,
  version = "1",

  params = { R = 0.04, m_s = 0.5, m_p = 0.5, g = 9.81 },
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },

  task = {
    stages = {
      { name = "first loop", targets = { u_ca = { value = { distance / 3, 0 }, tol = gate } } },
      { name = "second loop", targets = { u_ca = { value = { 2 * distance / 3, 0 }, tol = gate } } },
      { name = "onto the target, settled",
        targets = {
          u_ca = { value = { distance, 0 }, tol = 0.004 },
          p = { value = { 0, 0 }, tol = 0.008 },
          p_dot = { value = { 0, 0 }, tol = 0.01 },
          omega = { value = { 0, 0, 0 }, tol = 0.05 },
          u_co = { value = { 0, 0 }, tol = pi / 9 },
        },
        hold = 0.5 },
    },
    time_limit = 240,
  },

  score = function(s)
    if not s.success then return 100 * s.stages_passed end
    return math.floor(1000 * (1 - s.time / s.time_limit))
  end,
  medals = { bronze = 250, silver = 600, gold = 800 },  -- 180 s, 96 s, 48 s

  scene = { contact_trace = true, plots = { "u_a", "v_a", "psi" }, record_rate = 100, example_path = path },
  callbacks = {
    rate = 10,
    on_start = function(state)
      last_stage = 1
      hemiroll.message("Swirl: circles a turn every two seconds, tilt about 10 degrees, aimed a quarter turn off", 6)
    end,
    on_update = function(state)
      if state.stage ~= last_stage then
        last_stage = state.stage
        if state.stage == 2 then hemiroll.message("First gate. Keep swirling, steadily", 4) end
        if state.stage == 3 then
          hemiroll.message("Last loop onto the target; then let the circles die away and hold still", 5)
        end
      end
    end,
  },
}
