-- Challenge: a slalom of contact-point gates. Medium masses (m_s = 0.5 kg,
-- m_p = 0.5 kg): livelier than the tutorials, tamer than the paper's.
-- The gates lie on two loops round the start, so the way through is two
-- turns of precession (tutorial 3), the second one wider.

local gate = 0.002  -- [m], half-width per component

local gates = {
  { 0.004, 0 }, { 0, 0.004 }, { -0.004, 0 }, { 0, -0.004 },
  { 0.007, 0 }, { 0, 0.007 }, { -0.007, 0 }, { 0, -0.007 },
}
local stages = {}
for i, g in ipairs(gates) do
  stages[i] = { name = "gate " .. i, targets = { u_ca = { value = { g[1], g[2] }, tol = gate } } }
end
local last_stage = nil

return {
  name = "Slalom",
  description = "Steer the contact point through eight gates in order: a small loop (4 mm) and a " ..
    "wider one (7 mm), counter-clockwise from +x. Technique: precession; widen the tilt " ..
    "(mass point further out) for the second loop.",
  author = "hemiroll",
  difficulty = 3,
  version = "1",

  params = { R = 0.04, m_s = 0.5, m_p = 0.5, g = 9.81 },
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },

  task = {
    stages = stages,
    time_limit = 180,
    fail = { area = { name = "the table", shape = "box", min = { -0.05, -0.05 }, max = { 0.05, 0.05 } } },
  },

  score = function(s)
    local base = 100 * s.stages_passed
    if not s.success then return base end
    return base + math.floor(200 * (1 - s.time / s.time_limit))
  end,
  medals = { bronze = 800, silver = 900, gold = 950 },

  scene = { contact_trace = true, plots = { "u_a", "v_a" }, record_rate = 100 },
  callbacks = {
    rate = 20,
    on_start = function(state) last_stage = state.stage end,
    on_update = function(state)
      if state.stage ~= last_stage then
        hemiroll.message("Gate " .. last_stage .. " of " .. state.stage_count, 1.5)
        last_stage = state.stage
      end
    end,
    on_fail = function(state, reason) hemiroll.message("Out: " .. reason, 4) end,
  },
}
