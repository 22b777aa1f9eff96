-- A random task per seed from a wider family than random_reach.lua, for the
-- autopilot's generality checks (docs/AUTOPILOT.md, "Other bodies, couplings
-- and tasks"): `hemiroll run levels/generated/random_task.lua --bot autopilot
-- --seed N`. The seed picks the kind, KINDS[seed % 6 + 1], so that a range of
-- seeds covers each kind alike:
--   paper      the paper's body, coupling and tolerances, one stage
--   body       another body: R 3-5 cm, shell 0.08-0.5 kg, point 0.3-1.2 kg
--   coupling   another coupling: M1, M2 or M3, k_r 150-400 N/m, k_v 5-15
--              N s/m, alpha 1.5-3 (M3) with k_r alpha within the PHANToM
--              maker's 800 N/m
--   stages     two stages: reach, then hold still with psi in a band of 10-20
--              degrees
--   tolerance  every band 1-2 times the paper's
--   mixed      all of the above drawn at once
-- and, through hemiroll.random: the target contact point (1-8 cm away in
-- any direction) and, for half of the seeds, a shove at the start (the
-- hemisphere turning at up to 0.3 rad/s about each axis, the mass point
-- moving at up to 2 cm/s). 4 minutes, hold 0, like the paper's task.
-- Everything is SI: metres, seconds, radians, kilograms, newtons.

local pi = math.pi
local cm = 0.01

local KINDS = { "paper", "body", "coupling", "stages", "tolerance", "mixed" }
local kind = KINDS[hemiroll.seed() % #KINDS + 1]

local function uniform(a, b) return a + (b - a) * hemiroll.random() end

local mixed = kind == "mixed"
local params = { R = 4 * cm, m_s = 0.1, m_p = 1.0, g = 9.81 }
if kind == "body" or mixed then
  params = { R = uniform(3 * cm, 5 * cm), m_s = uniform(0.08, 0.5), m_p = uniform(0.3, 1.2), g = 9.81 }
end

local force = { method = "M3", kr = 250, kv = 10, alpha = 2 }
if kind == "coupling" or mixed then
  local methods = { "M1", "M2", "M3" }
  local kr = uniform(150, 400)
  force = { method = methods[hemiroll.random(3)], kr = kr, kv = uniform(5, 15), alpha = 1 }
  if force.method == "M3" then force.alpha = uniform(1.5, math.min(3, 800 / kr)) end
end

local scale = 1
if kind == "tolerance" or mixed then scale = uniform(1, 2) end

local distance = uniform(1 * cm, 8 * cm)
local heading = uniform(-pi, pi)
local reach = {
  u_ca = { value = { distance * math.cos(heading), distance * math.sin(heading) }, tol = 0.4 * cm * scale },
  p = { value = { 0, 0 }, tol = 0.4 * cm * scale },
  p_dot = { value = { 0, 0 }, tol = 0.4 * cm * scale },
  omega = { value = { 0, 0, 0 }, tol = 0.01 * scale },
  u_co = { value = { 0, 0 }, tol = pi / 18 * scale },
}

local task = { hold = 0, time_limit = 240 }
local two_stages = kind == "stages" or (mixed and hemiroll.random(2) == 2)
if two_stages then
  local psi_band = uniform(10, 20) * pi / 180
  task.stages = {
    { name = "reach", targets = reach },
    { name = "still, turned",
      targets = {
        p = { value = { 0, 0 }, tol = 0.4 * cm * scale },
        omega = { value = { 0, 0, 0 }, tol = 0.01 * scale },
        u_co = { value = { 0, 0 }, tol = pi / 18 * scale },
        psi = { value = uniform(-pi, pi), tol = psi_band },
      } },
  }
else
  task.targets = reach
end

local initial = nil
local shoved = hemiroll.random(2) == 2
if shoved then
  initial = { w_x = uniform(-0.3, 0.3), w_y = uniform(-0.3, 0.3), w_z = uniform(-0.3, 0.3),
              xd_p = uniform(-0.02, 0.02), yd_p = uniform(-0.02, 0.02) }
end

return {
  name = string.format("Random task (%s): %.1f cm at %.0f deg%s%s", kind, distance / cm, heading * 180 / pi,
                       two_stages and ", then psi" or "", shoved and ", shoved" or ""),
  description = "A random task drawn from the seed: another body, coupling, stages or tolerances.",
  author = "hemiroll",
  difficulty = 5,
  version = "1",
  params = params,
  initial = initial,
  force = force,
  task = task,
  score = function(s)
    if not s.success then return 0 end
    return s.time_limit - s.time
  end,
  scene = { contact_trace = true, plots = { "u_a", "v_a" }, record_rate = 100 },
}
