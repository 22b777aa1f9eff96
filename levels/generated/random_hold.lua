-- Random tasks that end with a hold, for the autopilot's settle law
-- (docs/AUTOPILOT.md, "Coming to rest"): `hemiroll run
-- levels/generated/random_hold.lua --bot autopilot --seed N`. The paper's
-- body and coupling, one kind ("hold"): the paper's task moved, reach,
-- stop and stay inside every band for the hold; and, through hemiroll.random: the target contact point (1-8 cm away in
-- any direction), every band 1-2 times the paper's, a hold of 0.1-1 s and,
-- for half of the seeds, a shove at the start (as random_task.lua). A
-- generator of its own, so that the seeds of random_task.lua keep their
-- tasks (docs/autopilot/task_seeds_0_199.txt). 4 minutes. Two stages with
-- a hold on a psi stage are not drawn, so that these seeds keep their
-- tasks (two such tasks are won, a family of them is not measured:
-- docs/AUTOPILOT.md, "What does not work yet").
-- Everything is SI: metres, seconds, radians, kilograms, newtons.

local pi = math.pi
local cm = 0.01

local kind = "hold"

local function uniform(a, b) return a + (b - a) * hemiroll.random() end

local scale = uniform(1, 2)
local hold = uniform(0.1, 1.0)
local distance = uniform(1 * cm, 8 * cm)
local heading = uniform(-pi, pi)
local reach = {
  u_ca = { value = { distance * math.cos(heading), distance * math.sin(heading) }, tol = 0.4 * cm * scale },
  p = { value = { 0, 0 }, tol = 0.4 * cm * scale },
  p_dot = { value = { 0, 0 }, tol = 0.4 * cm * scale },
  omega = { value = { 0, 0, 0 }, tol = 0.01 * scale },
  u_co = { value = { 0, 0 }, tol = pi / 18 * scale },
}

local task = { targets = reach, hold = hold, time_limit = 240 }

local initial = nil
local shoved = hemiroll.random(2) == 2
if shoved then
  initial = { w_x = uniform(-0.3, 0.3), w_y = uniform(-0.3, 0.3), w_z = uniform(-0.3, 0.3),
              xd_p = uniform(-0.02, 0.02), yd_p = uniform(-0.02, 0.02) }
end

return {
  name = string.format("Random task (%s): %.1f cm at %.0f deg, bands x%.2f, hold %.2f s%s", kind, distance / cm,
                       heading * 180 / pi, scale, hold, shoved and ", shoved" or ""),
  description = "A random task drawn from the seed that ends with a hold: reach, stop and stay.",
  author = "hemiroll",
  difficulty = 5,
  version = "1",
  params = { R = 4 * cm, m_s = 0.1, m_p = 1.0, g = 9.81 },
  initial = initial,
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },
  task = task,
  score = function(s)
    if not s.success then return 0 end
    return s.time_limit - s.time
  end,
  scene = { contact_trace = true, plots = { "u_a", "v_a" }, record_rate = 100 },
}
