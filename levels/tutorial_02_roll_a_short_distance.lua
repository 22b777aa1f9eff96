-- Tutorial 2: roll a short distance. The same forgiving masses as tutorial
-- 1. Rolling without slipping ties the contact point to the tilt: in a
-- straight roll u_a = -R u_o, so 4 mm of travel needs a tilt of 0.1 rad,
-- held by keeping the mass point off centre. Checked with `hemiroll sim`
-- (M3, kr 250, kv 10): a proxy eased over 2 s to x = 1.9, 2.1 or 2.3 cm (at
-- the face's height) and held there settles at u_a = 3.9, 4.05 and 4.1 mm,
-- inside this band, and the hold is met at about 3.9 s. A static proxy
-- gains little beyond that (3.5 mm at 4 cm: the mass point is pulled down
-- the tilted face), so the target sits where a simple controller gets.

return {
  name = "02 Roll a short distance",
  description = "Roll the hemisphere 4 mm to the right, onto the green target square on the floor (the " ..
    "green arrow points to it), and keep it still there for 2 s. Move the mass point slowly " ..
    "about 2 cm to the right and wait: the hemisphere leans, rolls until it balances, and " ..
    "stops. Then adjust a little at a time; the HUD says what is still off and by how much.",
  author = "hemiroll",
  difficulty = 1,
  version = "1",

  params = { R = 0.04, m_s = 1.0, m_p = 0.2, g = 9.81 },
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },

  task = {
    targets = {
      u_ca = { value = { 0.004, 0 }, tol = 0.0015 },
      omega_norm = { value = 0, tol = 0.02 },
      p_dot = { value = { 0, 0 }, tol = 0.003 },
    },
    hold = 2.0,
    time_limit = 60,
  },

  score = function(s)
    if not s.success then return 0 end
    return math.floor(1000 * (1 - s.time / s.time_limit))
  end,
  medals = { bronze = 500, silver = 800, gold = 900 },

  scene = { contact_trace = true, plots = { "u_a", "x_p" }, record_rate = 100 },
  callbacks = {
    rate = 10,
    on_start = function(state) hemiroll.message("Roll 4 mm to the right, onto the green square, and stay still", 4) end,
  },
}
