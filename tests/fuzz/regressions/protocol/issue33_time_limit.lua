return { experiment = 'e', blocks = { { level = 'tutorial_01_tilt_and_return.lua', time_limit = 1e16 } } }
