return {
  name = "one \z
     two",
  description = "a\
 b",
  task = { time_limit = 1e16 },
}
