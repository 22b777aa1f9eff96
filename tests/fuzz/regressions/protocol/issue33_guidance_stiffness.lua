return { experiment = 'e', blocks = { { level = 'tutorial_01_tilt_and_return.lua',
  guidance = { kind = 'autopilot', stiffness = 1e300, damping = 0 } } } }
