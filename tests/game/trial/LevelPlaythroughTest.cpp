// Playthroughs of the shipped level pack (levels/*.lua) by the shipped bots
// (scripts/bots/), in process: every level loads and survives the random
// bot; each level with a reference bot reaches its expected outcome and
// score band; a playthrough repeats bit for bit.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/script/BotScript.h"
#include "engine/script/LevelLoader.h"
#include "game/trial/BotTrial.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {
namespace {

using task::TrialOutcome;

const std::string kSource = HEMIROLL_SOURCE_DIR;

std::vector<std::string> shippedLevels() {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(kSource + "/levels"))
    if (entry.is_regular_file() && entry.path().extension() == ".lua") out.push_back(entry.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

// Plays `levelPath` with `bot` (a file under scripts/bots/); a time cap > 0
// shortens the level's time limit (for the robustness runs).
TrialResult play(const std::string& levelPath, const std::string& bot, std::uint64_t seed, double timeCap = 0.0) {
  script::LevelLoadOptions levelOptions;
  levelOptions.seed = seed;
  script::LoadedLevel level = script::LevelLoader(levelOptions).loadFile(levelPath);
  if (timeCap > 0.0) level.def.task.timeLimit = std::min(level.def.task.timeLimit, timeCap);
  script::BotLoadOptions botOptions;
  botOptions.seed = seed;
  script::BotScript script(kSource + "/scripts/bots/" + bot, botOptions);
  TrialSettings settings;
  settings.seed = seed;
  return BotTrial(level, script, settings).run();
}

TEST(LevelPlaythrough, ThePackIsThere) {
  EXPECT_GE(shippedLevels().size(), 6u) << "levels/ should hold the paper's level, tutorials and challenges";
}

// Every level, three seeds of the random bot, at most 3 s each: whatever
// the bot does, the trial ends with a reason, the state stays finite and no
// force above the device's limit is rendered.
TEST(LevelPlaythrough, EveryLevelSurvivesTheRandomBot) {
  for (const std::string& path : shippedLevels()) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const TrialResult r = play(path, "random.lua", seed, 3.0);
      SCOPED_TRACE(path + " seed " + std::to_string(seed) + ": " + r.reason);
      EXPECT_NE(r.outcome, TrialOutcome::Running);
      EXPECT_FALSE(r.reason.empty());
      EXPECT_TRUE(r.finalState.allFinite());
      EXPECT_LE(r.maxRenderedForce, botDeviceSpec().maxForce);
      EXPECT_LE(r.time, 3.0 + 0.0015);
      if (r.score) {
        EXPECT_TRUE(std::isfinite(*r.score));
      }
    }
  }
}

struct Reference {
  const char* level;
  const char* bot;
  TrialOutcome outcome;
  const char* reason;
  double minScore, maxScore;  // the band; see the table for why
};

std::ostream& operator<<(std::ostream& out, const Reference& r) { return out << r.level << " + " << r.bot; }

// Bands are medal bands of the level's own thresholds: the bots are
// deterministic, so a score outside its band means the level, the bot or the
// physics changed, which is what this test should catch; a band (not the
// exact score) leaves room for harmless retuning within a medal.
const Reference kReferences[] = {
    // 1000 (1 - t / 60): silver [800, 900) = done in 6-12 s (measured 9.4 s).
    {"tutorial_01_tilt_and_return.lua", "tutorial_solver.lua", TrialOutcome::Success, "target held", 800, 900},
    // bronze [500, 800) = done in 12-30 s (measured 17.6 s).
    {"tutorial_02_roll_a_short_distance.lua", "tutorial_solver.lua", TrialOutcome::Success, "target held", 500, 800},
    // 500 + 500 (1 - t / 120): gold [850, 1000] = done within 36 s (measured 29 s).
    {"tutorial_03_precess.lua", "tutorial_solver.lua", TrialOutcome::Success, "target held", 850, 1001},  // whole scores up to 1000
    // Watch-only, no score: the rose is watched to the end (35 s).
    {"rose_demo.lua", "rose.lua", TrialOutcome::Success, "watched to the end", 0, 0},
};

class ReferenceBotTest : public ::testing::TestWithParam<Reference> {};

TEST_P(ReferenceBotTest, ReachesTheExpectedOutcomeAndScoreBand) {
  const Reference& ref = GetParam();
  const TrialResult r = play(kSource + "/levels/" + ref.level, ref.bot, 0);
  EXPECT_EQ(r.outcome, ref.outcome) << r.reason;
  EXPECT_EQ(r.reason, ref.reason);
  if (ref.maxScore > ref.minScore) {
    ASSERT_TRUE(r.score.has_value());
    EXPECT_GE(*r.score, ref.minScore);
    EXPECT_LT(*r.score, ref.maxScore);
  } else {
    EXPECT_FALSE(r.score.has_value());
  }
}

INSTANTIATE_TEST_SUITE_P(Pack, ReferenceBotTest, ::testing::ValuesIn(kReferences), [](const auto& info) {
  std::string name = std::string(info.param.level).substr(0, std::strlen(info.param.level) - 4);
  std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
});

TEST(LevelPlaythrough, APlaythroughRepeatsBitForBit) {
  const std::string level = kSource + "/levels/tutorial_01_tilt_and_return.lua";
  const TrialResult a = play(level, "tutorial_solver.lua", 5), b = play(level, "tutorial_solver.lua", 5);
  EXPECT_EQ(a.ticks, b.ticks);
  EXPECT_EQ(a.score, b.score);
  EXPECT_EQ(std::memcmp(a.finalState.data(), b.finalState.data(), sizeof(double) * 12), 0);
}

}  // namespace
}  // namespace hemiroll::game
