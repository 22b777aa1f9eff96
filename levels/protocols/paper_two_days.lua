-- The paper's experiment as a research protocol: Svinin et al., "Dynamic
-- Model, Haptic Solution, and Human-Inspired Motion Planning for
-- Rolling-Based Manipulation", J. Comput. Inf. Sci. Eng. 9 (2009), Sec. 4.
-- Format: docs/PROTOCOLS.md. Run it for a person from the game's research
-- screen, or with a bot: hemiroll session levels/protocols/paper_two_days.lua
-- --participant p01 --bot scripts/bots/tutorial_solver.lua
--
-- Where every number comes from (section and paragraph of the paper):
--   the task: ../paper_reaching.lua (model, start, target, tolerances) .. Sec. 4, paras. 1-4
--   time limit: 4 min ............................................... Sec. 4, para. 4
--   two days: day 1 general evaluation, familiarisation and the
--             assessment of the force feedback methods .............. Sec. 4.1, para. 1
--   M1 and M2: k_r = 250 N/m, k_v = 10 N s/m ......................... Sec. 4.1, para. 2
--   M3: k_rx = k_ry = 250 N/m, k_vx = k_vy = 10 N s/m, alpha
--       varied from 1 to 4 ............................................ Sec. 4.1, para. 3
--       1.5 .. 2.5 stable and smooth, alpha = 2 preferred ............. Sec. 4.1, para. 4
--   visual only: f computed correctly, F_h zeroed .................... Sec. 4.1, para. 5
--   day 2: 15 trials, M3 with alpha = 2 ............................... Sec. 4.2, para. 1
--
-- Our choices, where the paper gives no number (change them freely):
--   the alpha grid 1, 1.5, 2, 2.5, 3, 4 (the paper names the range 1..4
--   and the values 1.5, 2, 2.5 and 4; 3 fills the gap); the number of
--   familiarisation trials (3) and of assessment trials per condition (2);
--   the assessment's random order (the paper does not give its order);
--   the familiarisation and visual-only gains (the paper does not say
--   which method or gains they used: the level's M3, alpha 2); the rest
--   between the blocks of day 1 (60 s); the randomisation seed.

local kr = 250          -- N/m,   Sec. 4.1, paras. 2 and 3
local kv = 10           -- N s/m, Sec. 4.1, paras. 2 and 3
local time_limit = 4 * 60  -- s,  Sec. 4, para. 4

local assessment = {
  { label = "M1", method = "M1", kr = kr, kv = kv },   -- Sec. 4.1, para. 2
  { label = "M2", method = "M2", kr = kr, kv = kv },   -- Sec. 4.1, para. 2
}
for _, alpha in ipairs({ 1, 1.5, 2, 2.5, 3, 4 }) do   -- Sec. 4.1, paras. 3 and 4 (3: ours)
  assessment[#assessment + 1] = { label = "M3 alpha " .. alpha, method = "M3", kr = kr, kv = kv, alpha = alpha }
end
-- Sec. 4.1, para. 5: the model is driven, the hand feels nothing.
assessment[#assessment + 1] = { label = "visual only", method = "visual", kr = kr, kv = kv, alpha = 2 }

return {
  experiment = "svinin2009-two-days",
  description = "Svinin et al. 2009, Sec. 4: day 1 familiarisation and the assessment of the " ..
    "force feedback methods M1, M2, M3 (alpha 1 to 4) and visual-only control; day 2 fifteen " ..
    "reaching trials with M3, alpha = 2, for analysis.",
  version = "1",
  seed = 2009,  -- ours: the assessment's order

  blocks = {
    -- Day 1 (Sec. 4.1, para. 1).
    {
      name = "day 1: familiarisation",
      label = "familiarisation",
      instructions = "Move the contact point to the target (4 cm back, 4 cm left) and stop there, " ..
        "upright and at rest, within 4 minutes. Take your time to get to know the system.",
      level = "paper_reaching.lua",
      time_limit = time_limit,
      repetitions = 3,  -- ours
      break_after = { message = "Rest for a minute. Next: the force feedback methods, in random order.",
                      min_duration = 60 },  -- ours
    },
    {
      name = "day 1: force feedback assessment",
      instructions = "The same task; the force feedback changes from trial to trial. " ..
        "Notice how each one feels.",
      level = "paper_reaching.lua",
      time_limit = time_limit,
      conditions = assessment,
      repetitions = 2,   -- ours
      randomise = true,  -- ours
      break_after = { message = "End of day 1. Day 2 (the data collection) continues from here " ..
                      "when the session is run again.", stop = true },  -- two days: Sec. 4.1, para. 1
    },
    -- Day 2 (Sec. 4.2, para. 1): 15 trials, M3 with alpha = 2.
    {
      name = "day 2: data collection",
      label = "M3 alpha 2",
      instructions = "Fifteen reaching trials with the same force feedback (M3).",
      level = "paper_reaching.lua",
      method = "M3", kr = kr, kv = kv, alpha = 2,
      time_limit = time_limit,
      repetitions = 15,
    },
  },
}
