local s = string.rep('x', 1e5)
s:gsub('', string.rep('%0', 1e5))
return { name = "x" }
