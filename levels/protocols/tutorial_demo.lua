-- A small protocol for demonstrations and tests (docs/PROTOCOLS.md): the
-- first two tutorials, with a short break between them and two couplings for
-- the second in random order. A bot plays it in well under a second:
--   hemiroll session levels/protocols/tutorial_demo.lua --participant demo \
--     --bot scripts/bots/tutorial_solver.lua

return {
  experiment = "tutorial-demo",
  description = "Tilt and return, then roll a short distance with two M3 gain ratios.",
  seed = 7,
  blocks = {
    {
      name = "tilt",
      instructions = "Tilt the hemisphere and bring it back upright.",
      level = "tutorial_01_tilt_and_return.lua",
      break_after = { message = "Well done. Next: roll a short distance.", min_duration = 3 },
    },
    {
      name = "roll",
      instructions = "Roll the hemisphere a short distance and stop on the target.",
      level = "tutorial_02_roll_a_short_distance.lua",
      method = "M3", kr = 250, kv = 10,
      conditions = {
        { label = "alpha 2", alpha = 2 },
        { label = "alpha 1.5", alpha = 1.5 },
      },
      randomise = true,
    },
  },
}
