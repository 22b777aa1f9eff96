local s = string.rep('', math.maxinteger)
return { experiment = 'e', blocks = { { level = 'tutorial_01_tilt_and_return.lua' } } }
