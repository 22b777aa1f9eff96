-- A between-subjects design in miniature (docs/PROTOCOLS.md "Groups and
-- counterbalancing"), for demonstrations and the tests of the study path:
--   three groups that differ only in training: guided towards the
--   autopilot's plan (fading), pushed away from it (error augmentation), or
--   left alone (control);
--   retention and transfer counterbalanced: half of each group plays
--   retention first, half transfer first (a balanced Latin square of two rows).
-- Participants get their group and order by arrival (assignment =
-- "balanced"): the k-th (0-based) group k mod 3, order (k div 3) mod 2 + 1.
-- Short tutorials and time limits, so that a cohort of simulated
-- participants runs in seconds:
--   hemiroll session levels/protocols/groups_demo.lua --participants 6 --bot human --human-device haptic

return {
  experiment = "groups-demo",
  description = "Three groups (guided, error augmented, control) trained on a short roll; retention and transfer counterbalanced.",
  version = "1",
  seed = 7,
  assignment = "balanced",
  groups = {
    { name = "guided", description = "training pulled towards the autopilot's plan, fading to none",
      changes = { { block = "training",
                    guidance = { kind = "autopilot", stiffness = 300, damping = 10,
                                 fade = { from = 1, to = 0, over_trials = 2 } } } } },
    { name = "augmented", description = "training pushed away from the autopilot's plan",
      changes = { { block = "training", guidance = { kind = "error_augmentation", gain = 100 } } } },
    { name = "control", description = "training without guidance" },
  },
  counterbalance = { "retention", "transfer" },
  blocks = {
    { name = "baseline", level = "tutorial_02_roll_a_short_distance.lua", time_limit = 8 },
    { name = "training", level = "tutorial_02_roll_a_short_distance.lua", time_limit = 8, repetitions = 2 },
    { name = "retention", level = "tutorial_02_roll_a_short_distance.lua", time_limit = 8 },
    { name = "transfer", level = "tutorial_01_tilt_and_return.lua", time_limit = 8 },
  },
}
