-- The guidance study of paper_guidance.lua as a between-subjects design
-- (docs/PROTOCOLS.md "Groups and counterbalancing"): three groups that
-- differ only in how they are trained on the paper's reaching task, and
-- retention and transfer counterbalanced within each group.
--   guided     training pulled towards the autopilot's plan (300 N/m,
--              10 N s/m), fading from full to none over the 12 trials;
--   augmented  training pushed away from the plan (error augmentation,
--              100 N/m, 10 N s/m, not faded);
--   control    training without guidance.
-- Every group: baseline (3), training (12), a five-minute break, then
-- retention (3) and transfer (3) in the participant's order (half of each
-- group one way, half the other). Participants get their group and order
-- by arrival. The guidance gains are paper_guidance.lua's; the error
-- augmentation's gain is ours (a third of the guiding spring, under the
-- 3 N force limit within the 2 cm reach). A simulated cohort:
--   hemiroll session levels/protocols/paper_guidance_groups.lua --participants 12 --bot human --human-device haptic

return {
  experiment = "paper-guidance-groups",
  description = "The paper's reaching task: three training groups (guided with fading, error augmented, " ..
    "control); retention and transfer counterbalanced.",
  version = "1",
  seed = 2009,
  assignment = "balanced",
  groups = {
    { name = "guided", description = "training pulled towards the autopilot's plan, fading to none",
      changes = { { block = "training", guidance = { kind = "autopilot", stiffness = 300, damping = 10,
                                                     fade = { from = 1, to = 0, over_trials = 12 } } } } },
    { name = "augmented", description = "training pushed away from the autopilot's plan",
      changes = { { block = "training", guidance = { kind = "error_augmentation", gain = 100, damping = 10 } } } },
    { name = "control", description = "training without guidance" },
  },
  counterbalance = { "retention", "transfer" },
  blocks = {
    {
      name = "baseline",
      instructions = "Move the contact point to the target on your own.",
      level = "paper_reaching.lua",
      repetitions = 3,
    },
    {
      name = "training",
      instructions = "Move the contact point to the target; the device may push or pull your hand.",
      level = "paper_reaching.lua",
      repetitions = 12,
      break_after = { message = "Rest for five minutes.", min_duration = 300 },
    },
    {
      name = "retention",
      instructions = "On your own again: move the contact point to the target.",
      level = "paper_reaching.lua",
      repetitions = 3,
    },
    {
      name = "transfer",
      instructions = "A new target: 4 cm back and 4 cm to the right.",
      level = "paper_reaching_transfer.lua",
      repetitions = 3,
    },
  },
}
