#pragma once
// A level's medal thresholds as times, where its score is a time (issue 27:
// "bronze 70, silver 194, gold 200 points" means "in 170 s, 46 s, 40 s").
// A score function is Lua, so it is asked rather than read: the level's
// score for a success at times across its limit (the other summary fields
// as a clean success has them). When that score falls with time and with
// nothing else, each medal's time is the longest a success may take and
// still score it (to 0.01 s). Any other score (one that counts gates, say,
// or does not fall with time) gives none, and the thresholds stay points.

#include <optional>

#include "engine/script/LevelLoader.h"

namespace hemiroll::game {

struct MedalTimes {
  double bronze = 0.0, silver = 0.0, gold = 0.0;  // [s] at most, for each medal
};

std::optional<MedalTimes> medalTimes(script::LoadedLevel& level);

// "gold in 40 s, silver 46 s, bronze 170 s" when `times`, else
// "bronze 70, silver 194, gold 200 points"; "" without medals.
std::string medalLine(const task::ScoringDef& scoring, const std::optional<MedalTimes>& times);

}  // namespace hemiroll::game
