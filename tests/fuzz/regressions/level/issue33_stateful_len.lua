local n = 0
local t = setmetatable({}, { __len = function() n = n + 1 return n == 1 and 0 or 1e15 end })
table.insert(t, 1, 1)
table.concat(t)
return { name = "x" }
