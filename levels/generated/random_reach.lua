-- A random reaching task per seed, for the autopilot's generality checks
-- (docs/AUTOPILOT.md): `hemiroll run levels/generated/random_reach.lua
-- --bot autopilot --seed N`. The seed picks, through hemiroll.random:
--   - the target contact point: up to 8 cm away in any direction (distance
--     uniform in 1-8 cm, direction uniform);
--   - on odd draws, a psi target within pi/18 as well (uniform in (-pi, pi]);
--   - the start: from rest (half of the seeds) or shoved (the hemisphere
--     already turning at up to 0.3 rad/s about each axis, the mass point
--     moving at up to 2 cm/s), upright with the mass point at the centre.
-- Everything else is the paper's task (masses, coupling, every tolerance,
-- 4 minutes, hold = 0): paper_reaching.lua is the seed-free instance.

local pi = math.pi
local cm = 0.01

local function uniform(a, b) return a + (b - a) * hemiroll.random() end

local distance = uniform(1 * cm, 8 * cm)
local heading = uniform(-pi, pi)
local with_psi = hemiroll.random(2) == 2
local shoved = hemiroll.random(2) == 2

local targets = {
  u_ca = { value = { distance * math.cos(heading), distance * math.sin(heading) }, tol = 0.4 * cm },
  p = { value = { 0, 0 }, tol = 0.4 * cm },
  p_dot = { value = { 0, 0 }, tol = 0.4 * cm },
  omega = { value = { 0, 0, 0 }, tol = 0.01 },
  u_co = { value = { 0, 0 }, tol = pi / 18 },
}
if with_psi then targets.psi = { value = uniform(-pi, pi), tol = pi / 18 } end

local initial = nil
if shoved then
  initial = { w_x = uniform(-0.3, 0.3), w_y = uniform(-0.3, 0.3), w_z = uniform(-0.3, 0.3),
              xd_p = uniform(-0.02, 0.02), yd_p = uniform(-0.02, 0.02) }
end

return {
  name = string.format("Random reach: %.1f cm at %.0f deg%s%s", distance / cm, heading * 180 / pi,
                       with_psi and ", psi" or "", shoved and ", shoved" or ""),
  description = "A random reaching task drawn from the seed (the paper's task with another target).",
  author = "hemiroll",
  difficulty = 5,
  version = "1",
  params = { R = 4 * cm, m_s = 0.1, m_p = 1.0, g = 9.81 },
  initial = initial,
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },
  task = { targets = targets, hold = 0, time_limit = 240 },
  score = function(s)
    if not s.success then return 0 end
    return s.time_limit - s.time
  end,
  scene = { contact_trace = true, plots = { "u_a", "v_a" }, record_rate = 100 },
}
