return {
  params = { R = 0.04, m_s = 0.1, m_p = 1.0, g = 9.81 },
  drive = { kind = "proxy", method = "M3", kr = 250, kv = 10, alpha = 2,
            proxy = function(t) local s = string.rep('', math.maxinteger) return 0.004, 0, 0.04 end },
  duration = 0.01, dt = 0.001,
}
