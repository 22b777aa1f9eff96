-- Challenge: a time trial. Tutorial 2's task turned 90 degrees (5 mm
-- along +y) with medium masses and a 30 s limit; the score is the time
-- left, so every second counts. A countdown appears in the last 10 s.

local warned = false

return {
  name = "Time trial",
  description = "Roll the contact point 5 mm along +y and hold it still for 1 s, as fast as you can. " ..
    "Technique: one decisive move of the mass point towards +y, then let it settle; " ..
    "overshoot costs more than patience.",
  author = "hemiroll",
  difficulty = 2,
  version = "1",

  params = { R = 0.04, m_s = 0.5, m_p = 0.5, g = 9.81 },
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },

  task = {
    targets = {
      u_ca = { value = { 0, 0.005 }, tol = 0.0015 },
      omega_norm = { value = 0, tol = 0.03 },
    },
    hold = 1.0,
    time_limit = 30,
  },

  score = function(s)
    if not s.success then return 0 end
    return s.time_limit - s.time  -- seconds to spare
  end,
  medals = { bronze = 10, silver = 20, gold = 25 },  -- done in 20 s, 10 s, 5 s

  scene = { contact_trace = true, plots = { "v_a", "y_p" }, record_rate = 100 },
  callbacks = {
    rate = 10,
    on_start = function(state) warned = false end,
    on_update = function(state)
      if not warned and state.t >= state.time_limit - 10 then
        warned = true
        hemiroll.message("10 seconds left!", 2)
      end
    end,
  },
}
