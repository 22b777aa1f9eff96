local a = string.rep('a', 1 << 22)
local b = string.rep('a', (1 << 21) - 1) .. 'b'
a:find(b, 1, true)
return { name = "x" }
