table.move({}, 1, 1e15, 1, {})
return { duration = 1, axes = { { param = 'k', values = { 4, 8 } } } }
