-- Tutorial 1: tilt and return. A heavy shell (1 kg) and a light mass
-- point (0.2 kg) make the hemisphere slow and forgiving: 1.5 cm of the mass
-- point off centre tilts it by about 5 degrees. Checked with `hemiroll sim`
-- (M3, kr 250, kv 10): a proxy eased to x = 1.5 cm over 1.5 s gives u_o =
-- -0.087 rad at rest (stage 1 passes at 1.3 s); eased back to the centre
-- from 4 s to 5.5 s, the hemisphere meets stage 2 at 6.7 s.

local told_to_return = false  -- level state lives in locals of this file

return {
  name = "01 Tilt and return",
  description = "Take hold, then move the mouse slowly to the right, about 1.5 cm of the mass " ..
    "point: the hemisphere leans about 5 degrees that way (the way the red stripe on its face " ..
    "points at the start) and rolls a little. The tilt gauge in the top left shows the lean. " ..
    "Hold it for half a " ..
    "second, then bring the mass point back to the middle and let the hemisphere stand upright " ..
    "and still for 1 s. Move slowly: the spring between your hand and the mass point does the rest.",
  author = "hemiroll",
  difficulty = 1,
  version = "1",

  params = { R = 0.04, m_s = 1.0, m_p = 0.2, g = 9.81 },
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },

  task = {
    stages = {
      { name = "tilt towards +x",
        targets = { u_co = { value = { -0.08, 0 }, tol = 0.03 } },
        hold = 0.5 },
      { name = "back upright and still",
        targets = {
          u_co = { value = { 0, 0 }, tol = 0.01 },
          p = { value = { 0, 0 }, tol = 0.002 },
          omega_norm = { value = 0, tol = 0.02 },
        },
        hold = 1.0 },
    },
    time_limit = 60,
  },

  score = function(s)
    if not s.success then return 0 end
    return math.floor(1000 * (1 - s.time / s.time_limit))
  end,
  medals = { bronze = 500, silver = 800, gold = 900 },  -- 30 s, 12 s, 6 s

  scene = { contact_trace = true, plots = { "u_o", "x_p" }, record_rate = 100 },
  callbacks = {
    rate = 10,
    on_start = function(state)
      told_to_return = false
      hemiroll.message("Lean the hemisphere to the right: about 5 degrees on the tilt gauge", 4)
    end,
    on_update = function(state)
      if state.stage == 2 and not told_to_return then
        told_to_return = true
        hemiroll.message("Good. Now the mass point back to the middle: upright and still", 4)
      end
    end,
    on_success = function(state) hemiroll.message("Well done!", 3) end,
  },
}
