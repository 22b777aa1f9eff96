// game/trial/AutopilotBot through the real trial loop (BotTrial: servo
// loop, coupling, ramp, safety, judge): the shipped levels it must win, a few
// generated tasks, determinism per seed, and refusals with "autopilot: ...".

#include "game/trial/AutopilotBot.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "engine/script/LevelLoader.h"
#include "game/trial/BotTrial.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {
namespace {

using task::TrialOutcome;

const std::string kLevels = std::string(HEMIROLL_SOURCE_DIR) + "/levels/";

TrialResult playFile(const std::string& path, std::uint64_t seed = 0) {
  script::LevelLoadOptions options;
  options.seed = seed;
  script::LoadedLevel level = script::LevelLoader(options).loadFile(path);
  AutopilotBot bot;
  TrialSettings settings;
  settings.seed = seed;
  return BotTrial(level, bot, settings).run();
}

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TrialResult playSource(const char* source) {
  script::LoadedLevel level = script::LevelLoader().loadSource(source, "level.lua");
  AutopilotBot bot;
  return BotTrial(level, bot, TrialSettings{}).run();
}

TEST(AutopilotBot, WinsThePapersTaskWithGold) {
  const TrialResult r = playFile(kLevels + "paper_reaching.lua");
  ASSERT_EQ(r.outcome, TrialOutcome::Success) << r.reason;
  EXPECT_EQ(r.medal, task::Medal::Gold);  // under 40 s
  EXPECT_LE(r.maxRenderedForce, botDeviceSpec().maxForce);
}

// Every tutorial, the first included: a lean asked for with no contact
// point to reach (tutorial 01) once left the autopilot standing still for
// the whole minute, so that watching it on the first level showed nothing.
TEST(AutopilotBot, WinsEveryTutorial) {
  for (const char* name : {"tutorial_01_tilt_and_return.lua", "tutorial_02_roll_a_short_distance.lua",
                           "tutorial_03_precess.lua", "tutorial_06_papers_hemisphere.lua"}) {
    const TrialResult r = playFile(kLevels + name);
    EXPECT_EQ(r.outcome, TrialOutcome::Success) << name << ": " << r.reason;
  }
}

TEST(AutopilotBot, WinsTutorialFour) {
  const TrialResult r = playFile(kLevels + "tutorial_04_stop_on_target.lua");
  EXPECT_EQ(r.outcome, TrialOutcome::Success) << r.reason;
}

// The helix tutorial can be won as shipped: its gates, its stop (measured:
// 103.6 s, seed 0), not only by the example path it draws.
TEST(AutopilotBot, WinsTheHelixTutorial) {
  const TrialResult r = playFile(kLevels + "tutorial_05_helix.lua");
  EXPECT_EQ(r.outcome, TrialOutcome::Success) << r.reason;
  EXPECT_EQ(r.summary.stagesPassed, 3);
}

TEST(AutopilotBot, WinsEveryChallenge) {
  for (const char* name : {"challenge_slalom.lua", "challenge_time_trial.lua", "challenge_full_orientation.lua",
                           "challenge_forbidden_zone.lua"}) {
    const TrialResult r = playFile(kLevels + name);
    EXPECT_EQ(r.outcome, TrialOutcome::Success) << name << ": " << r.reason;
  }
}

TEST(AutopilotBot, WinsGeneratedTasks) {
  // Seeds 4 (2.8 cm), 5 (3.0 cm, shoved) and 9 (1.0 cm with a psi band):
  // one of each kind; tools/autopilot-success.sh plays all 100
  // (docs/AUTOPILOT.md gives the rate).
  for (const std::uint64_t seed : {4u, 5u, 9u}) {
    const TrialResult r = playFile(kLevels + "generated/random_reach.lua", seed);
    EXPECT_EQ(r.outcome, TrialOutcome::Success) << "seed " << seed << ": " << r.reason;
  }
}

// The widened generator (issue 28): one seed of each kind it draws, won
// headless (tools/autopilot-success.sh plays seeds 0-199, 200 of 200 won;
// docs/AUTOPILOT.md). The level's name says which kind the seed drew, so a
// change to the generator that moves a kind off its seed fails here too.
TEST(AutopilotBot, WinsEachKindOfTheWidenedGenerator) {
  const std::pair<std::uint64_t, const char*> seeds[] = {
      {174, "(paper)"}, {199, "(body)"}, {32, "(coupling)"}, {135, "(stages)"}, {136, "(tolerance)"}, {17, "(mixed)"}};
  for (const auto& [seed, kind] : seeds) {
    script::LevelLoadOptions options;
    options.seed = seed;
    script::LoadedLevel level = script::LevelLoader(options).loadFile(kLevels + "generated/random_task.lua");
    EXPECT_NE(level.def.name.find(kind), std::string::npos) << seed << ": " << level.def.name;
    AutopilotBot bot;
    TrialSettings settings;
    settings.seed = seed;
    const TrialResult r = BotTrial(level, bot, settings).run();
    EXPECT_EQ(r.outcome, TrialOutcome::Success) << level.def.name << ": " << r.reason;
  }
}

// Holds (issue 28): the paper's task with a hold of 0.1 s, and a
// researcher's two stages written from the docs (reach 5 cm at 45 degrees
// and hold still, then psi within 20 degrees and hold still; p 6 mm, omega
// 0.02 rad/s), once lost at 13.2 s (landings passed through the bands; the
// planning budget ran out). docs/AUTOPILOT.md has the generated hold tasks.
TEST(AutopilotBot, WinsTasksWithHolds) {
  std::string source = readFile(kLevels + "paper_reaching.lua");
  const std::string shipped = "hold = 0,";
  source.replace(source.find(shipped), shipped.size(), "hold = 0.1,");
  script::LoadedLevel level = script::LevelLoader().loadSource(source, "paper_hold.lua");
  AutopilotBot bot;
  const TrialResult paper = BotTrial(level, bot, TrialSettings{}).run();
  EXPECT_EQ(paper.outcome, TrialOutcome::Success) << paper.reason;
  EXPECT_EQ(paper.medal, script::Medal::Gold);

  const TrialResult twoStages = playSource(R"lua(
local pi = math.pi
return { name = "reach and hold, then psi", params = { R = 0.04, m_s = 0.1, m_p = 1.0, g = 9.81 },
  force = { method = "M3", kr = 250, kv = 10, alpha = 2 },
  task = { stages = {
    { targets = { u_ca = { value = { 0.05 * math.cos(pi / 4), 0.05 * math.sin(pi / 4) }, tol = 0.006 },
                  p = { value = { 0, 0 }, tol = 0.006 }, p_dot = { value = { 0, 0 }, tol = 0.006 },
                  omega = { value = { 0, 0, 0 }, tol = 0.02 }, u_co = { value = { 0, 0 }, tol = pi / 12 } },
      hold = 1.0 },
    { targets = { p = { value = { 0, 0 }, tol = 0.006 }, omega = { value = { 0, 0, 0 }, tol = 0.02 },
                  psi = { value = -2.0, tol = 20 * pi / 180 } },
      hold = 1.0 } }, time_limit = 120 } }
)lua");
  EXPECT_EQ(twoStages.outcome, TrialOutcome::Success) << twoStages.reason;
  EXPECT_EQ(twoStages.summary.stagesPassed, 2);
}

// The holds' generator (levels/generated/random_hold.lua): two seeds, one
// shoved (seed 0: 1.7 cm, hold 0.77 s) and one not (seed 9); the tool plays
// seeds 0-59, 60 of 60 won (docs/AUTOPILOT.md).
TEST(AutopilotBot, WinsGeneratedHoldTasks) {
  for (const std::uint64_t seed : {0u, 9u}) {
    script::LevelLoadOptions options;
    options.seed = seed;
    script::LoadedLevel level = script::LevelLoader(options).loadFile(kLevels + "generated/random_hold.lua");
    EXPECT_NE(level.def.name.find("(hold)"), std::string::npos) << seed << ": " << level.def.name;
    AutopilotBot bot;
    TrialSettings settings;
    settings.seed = seed;
    const TrialResult r = BotTrial(level, bot, settings).run();
    EXPECT_EQ(r.outcome, TrialOutcome::Success) << level.def.name << ": " << r.reason;
  }
}

TEST(AutopilotBot, WinsWithEveryForceMethodAndStiffnessRatio) {
  // The paper's task with M1, M2 and M3 at alpha = 1..4 (Sec. 4.1's range).
  const std::string paper = kLevels + "paper_reaching.lua";
  for (const char* force : {"method = \"M1\", kr = 250, kv = 10, alpha = 1", "method = \"M2\", kr = 250, kv = 10, alpha = 1",
                            "method = \"M3\", kr = 250, kv = 10, alpha = 3", "method = \"M3\", kr = 250, kv = 10, alpha = 4"}) {
    std::string source = readFile(paper);
    const std::string shipped = "method = \"M3\", kr = 250, kv = 10, alpha = 2";
    source.replace(source.find(shipped), shipped.size(), force);
    script::LoadedLevel level = script::LevelLoader().loadSource(source, "paper_variant.lua");
    AutopilotBot bot;
    const TrialResult r = BotTrial(level, bot, TrialSettings{}).run();
    EXPECT_EQ(r.outcome, TrialOutcome::Success) << force << ": " << r.reason;
  }
}

TEST(AutopilotBot, SameSeedSameTrialBitForBit) {
  const TrialResult a = playFile(kLevels + "paper_reaching.lua", 7);
  const TrialResult b = playFile(kLevels + "paper_reaching.lua", 7);
  EXPECT_EQ(a.ticks, b.ticks);
  EXPECT_EQ(std::memcmp(a.finalState.data(), b.finalState.data(), sizeof(double) * 12), 0);
}

TEST(AutopilotBot, SaysInOneLineWhyATargetIsOutOfReach) {
  const TrialResult beyond = playSource(R"lua(
return { name = "far", task = { targets = { u_ca = { value = {0.5, 0.5}, tol = 0.004 } }, time_limit = 60 } }
)lua");
  EXPECT_EQ(beyond.outcome, TrialOutcome::Failure);
  EXPECT_EQ(beyond.reason.rfind("autopilot: the target contact point", 0), 0u) << beyond.reason;
  EXPECT_LT(beyond.time, 0.01);

  const TrialResult rim = playSource(R"lua(
return { name = "rim", task = { targets = { u_co = { value = {1.7, 0}, tol = 0.05 } }, time_limit = 60 } }
)lua");
  EXPECT_EQ(rim.reason.rfind("autopilot: the target tilt", 0), 0u) << rim.reason;

  // Contradictory stages: the second asks for rest at a tilt that the first's
  // mass point band rules out. The autopilot says so when it reaches it.
  const TrialResult contradictory = playSource(R"lua(
return { name = "contradiction", task = { stages = {
  { targets = { u_co = { value = {0, 0}, tol = 0.2 } } },
  { targets = { u_co = { value = {0.6, 0}, tol = 0.05 }, p = { value = {0, 0}, tol = 0.002 },
                omega = { value = {0, 0, 0}, tol = 0.01 } } } }, time_limit = 60 } }
)lua");
  EXPECT_EQ(contradictory.outcome, TrialOutcome::Failure);
  EXPECT_EQ(contradictory.reason.rfind("autopilot: the stage asks for rest", 0), 0u) << contradictory.reason;
  EXPECT_LT(contradictory.time, 1.0);
}

}  // namespace
}  // namespace hemiroll::game
