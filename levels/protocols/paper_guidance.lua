-- A haptic guidance study of the paper's reaching task (docs/PROTOCOLS.md
-- "Guidance"), in the classic four phases of motor-learning studies:
--   baseline   3 trials without guidance: where the participant starts;
--   training  12 trials guided by the autopilot: the device pulls the hand
--              towards the autopilot's plan with a 300 N/m spring and a
--              10 N s/m damper, fading linearly from full (trial 1) to none
--              (trial 12), so that the last trials are the participant's own;
--   retention  3 trials without guidance, after a break: what was learned;
--   transfer   3 trials on the mirrored target (4 cm back and right): whether
--              it generalises beyond the trained movement.
-- The paper's task, time limit (4 min) and coupling (M3, kr 250 N/m, kv 10
-- N s/m, alpha 2) throughout. A bot plays it headless:
--   hemiroll session levels/protocols/paper_guidance.lua --participant p01 --bot passive-hand
-- (passive-hand only yields to the device: it shows what the guidance does alone).

return {
  experiment = "paper-guidance",
  description = "The paper's reaching task: baseline, autopilot-guided training with fading, " ..
    "retention without guidance, transfer to a mirrored target.",
  version = "1",
  seed = 2009,
  blocks = {
    {
      name = "baseline",
      instructions = "Move the contact point to the target on your own.",
      level = "paper_reaching.lua",
      repetitions = 3,
    },
    {
      name = "training",
      instructions = "The device now guides you along the autopilot's path. Let it lead, and feel " ..
        "the rhythm of the circling; the guidance fades as you go.",
      level = "paper_reaching.lua",
      guidance = {
        kind = "autopilot", stiffness = 300, damping = 10,  -- N/m, N s/m
        fade = { from = 1, to = 0, over_trials = 12 },
      },
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
