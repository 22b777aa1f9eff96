return { name = "escape", act = function(t, obs)
  table.move({}, 1, 1e15, 1, {})
  return 0, 0, 0.04
end }
