-- rose: the double-pendulum ("rose") actuation of Svinin et al., Sec. 5,
-- eqs. (49)-(50), played through the haptic coupling instead of prescribed:
-- the bot moves the proxy so that the mass point traces, on the face,
--   p_d(t) = (r1 cos(phi) + r2 cos(k phi), r1 sin(phi) - r2 sin(k phi)),
-- phi = Omega t, with the paper's r1 = 1.5 cm, r2 = 0.8 cm, k = 8,
-- Omega = -pi/10 rad/s (nine leaves, first link clockwise).
--
-- Derivation. The proxy is in the scene frame, the curve on the face, so the
-- bot maps face coordinates to the scene with what it observes each tick:
--   scene(q) = centre + q_x * face_x + q_y * face_y.
-- With the proxy at scene(p_d), the spring alone would leave the mass point
-- short of the curve by the force it needs / k_r. That force (in the face,
-- eq. 46) is f = m_p (p_d'' - q), q the in-face acceleration the rolling face
-- gives a free particle; its dominant part is gravity along the tilted
-- face, q ~ g_face = (g . face_x, g . face_y), g = (0, 0, -g). So the proxy
-- goes to scene(p_d + m_p (p_d'' - g_face) / k_r)  (feed-forward),
-- plus gain * (p_d - p) (feedback on the observed face point, which removes
-- what the feed-forward leaves: the rolling terms and the spring's lag).
-- The proxy stays in the face plane: the normal load is the face's.
--
-- Start: the proxy sits on the mass point until the coupling engages (the
-- device engages within 1 cm); a level that starts the mass point away from
-- the curve is blended onto it over `blend` seconds. The prescribed drive
-- starts on the curve with its velocity, p(0) = (r1 + r2, 0),
-- p'(0) = (0, Omega (r1 - k r2)); a level with that initial state needs no
-- blend and the two agree closely for the first seconds (tests).
--
-- Checked in tests/game/RosePlaythroughTest.cpp against the 8-state
-- prescribed drive of the same curve (hemiroll sim levels/scenarios/rose_paper.lua).

local bot = { name = "rose" }

local r1, r2, k, Omega = 0.015, 0.008, 8, -math.pi / 10
local gain = 2.0    -- feedback on the face point [-]: the spring's k_r times (1 + gain) on the error
local blend = 1.0   -- [s] onto the curve when the level starts elsewhere
local m_p, kr, g = 1.0, 250.0, 9.81
local engaged_at, start_x, start_y

local cos, sin = math.cos, math.sin

function bot.init(level, seed)
  m_p, kr, g = level.m_p, level.kr, level.g
end

function bot.act(t, obs)
  local s = obs.state
  if not obs.engaged and not engaged_at then
    local m = obs.mass
    return m.x, m.y, m.z
  end
  local phi = Omega * t
  local c1, s1, ck, sk = cos(phi), sin(phi), cos(k * phi), sin(k * phi)
  local px, py = r1 * c1 + r2 * ck, r1 * s1 - r2 * sk
  local w2 = Omega * Omega
  local ax, ay = -w2 * (r1 * c1 + k * k * r2 * ck), -w2 * (r1 * s1 - k * k * r2 * sk)

  -- Where the mass point was off the curve at engagement, that offset fades
  -- out (smoothstep) over `blend` seconds; on the curve it is zero.
  if not engaged_at then engaged_at, start_x, start_y = t, s.x_p - px, s.y_p - py end
  local u = (t - engaged_at) / blend
  if u < 1 then
    local w = 1 - u * u * (3 - 2 * u)
    px, py = px + w * start_x, py + w * start_y
  end

  local fx, fy, n = obs.face_x, obs.face_y, obs.centre
  local gfx, gfy = -g * fx.z, -g * fy.z                -- gravity along the face
  local ox = px + m_p * (ax - gfx) / kr + gain * (px - s.x_p)
  local oy = py + m_p * (ay - gfy) / kr + gain * (py - s.y_p)
  return n.x + ox * fx.x + oy * fy.x, n.y + ox * fx.y + oy * fy.y, n.z + ox * fx.z + oy * fy.z
end

return bot
