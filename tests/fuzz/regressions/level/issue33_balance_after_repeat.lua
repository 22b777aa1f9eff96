local s = string.rep('(', 5000)
s:find('.-%b()')
return { name = "x" }
