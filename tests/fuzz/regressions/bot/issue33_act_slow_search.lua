local s = string.rep('(', 14000)
return { name = "slow", act = function(t, obs) s:find('%b()') return 0, 0, 0.04 end }
