// levels/: every shipped level loads, scores and runs its callbacks without
// error; the paper's level carries the paper's numbers (Sec. 4) exactly.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "engine/script/LevelLoader.h"
#include "engine/script/ScriptError.h"
#include "engine/task/TrialSummaryAccumulator.h"

namespace hemiroll::script {
namespace {

std::vector<std::string> shippedLevels() {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(HEMIROLL_SOURCE_DIR) / "levels"))
    if (entry.is_regular_file() && entry.path().extension() == ".lua") out.push_back(entry.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

LevelLoadOptions repositoryOptions() {
  LevelLoadOptions options;
  options.scriptsDir = (std::filesystem::path(HEMIROLL_SOURCE_DIR) / "scripts").string();
  return options;
}

TEST(LevelPack, ShipsTheLadderThePaperAndTheChallenges) {
  std::set<std::string> names;
  for (const std::string& path : shippedLevels()) names.insert(std::filesystem::path(path).stem().string());
  for (const char* required : {"paper_reaching", "tutorial_01_tilt_and_return", "tutorial_02_roll_a_short_distance",
                               "tutorial_03_precess", "tutorial_04_stop_on_target", "challenge_full_orientation",
                               "challenge_slalom", "challenge_time_trial", "challenge_forbidden_zone", "rose_demo"})
    EXPECT_EQ(names.count(required), 1u) << required;
}

// Loads every level, runs its callbacks through a short trial at rest and
// scores it: any Lua mistake in a shipped level fails here.
TEST(LevelPack, EveryLevelLoadsRunsAndScores) {
  std::set<std::string> titles;
  for (const std::string& path : shippedLevels()) {
    SCOPED_TRACE(path);
    LoadedLevel level;
    try {
      level = LevelLoader(repositoryOptions()).loadFile(path);
    } catch (const ScriptError& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    EXPECT_TRUE(titles.insert(level.def.name).second) << "duplicate name " << level.def.name;
    EXPECT_FALSE(level.def.description.empty());
    TaskJudge judge(level.def.task);
    TrialSummaryAccumulator summary;
    TrialObservation obs;
    for (int tick = 0; tick <= 2000 && !judge.finished(); ++tick) {  // 2 s at rest
      obs.time = tick * 0.001;
      JudgeInput in;
      in.time = obs.time;
      judge.judge(in);
      summary.add(in, {}, judge);
      level.script->update(obs, judge);
    }
    EXPECT_EQ(level.script->scriptError(), "");
    const ScoreResult score = level.script->score(summary.summary(judge));
    EXPECT_EQ(score.error, "");
    if (level.def.scoring.hasScoreFunction) {
      ASSERT_TRUE(score.score.has_value());
      EXPECT_TRUE(std::isfinite(*score.score));
    }
  }
}

TEST(LevelPack, ThePapersLevelIsThePapersExperiment) {
  const LevelDef d =
      LevelLoader(repositoryOptions()).loadFile(std::string(HEMIROLL_SOURCE_DIR) + "/levels/paper_reaching.lua").def;
  // Svinin et al. 2009, Sec. 4 and 4.1 (the values are the specification).
  EXPECT_EQ(d.params.gravity, 9.81);
  EXPECT_EQ(d.params.pointMass, 1.0);
  EXPECT_EQ(d.params.shellMass, 0.1);
  EXPECT_EQ(d.params.radius, 0.04);
  EXPECT_EQ(d.initial, physics::ForceDrivenState::Zero());
  EXPECT_EQ(d.coupling.method, physics::ForceMethod::M3);
  EXPECT_EQ(d.coupling.stiffness, 250.0);
  EXPECT_EQ(d.coupling.damping, 10.0);
  EXPECT_EQ(d.coupling.alpha, 2.0);
  EXPECT_EQ(d.task.timeLimit, 240.0);
  EXPECT_THAT(d.description, ::testing::HasSubstr("PAPER'S EXPERIMENT"));
  ASSERT_EQ(d.task.stages.size(), 1u);
  const auto& targets = d.task.stages[0].targets;
  ASSERT_EQ(targets.size(), 11u);  // every slot but psi
  for (const TargetDef& t : targets) {
    SCOPED_TRACE(taskVariableName(t.variable));
    EXPECT_NE(t.variable, TaskVariable::psi);
    switch (t.variable) {
      case TaskVariable::u_a:
      case TaskVariable::v_a:
        EXPECT_DOUBLE_EQ(t.value, -0.04);
        EXPECT_DOUBLE_EQ(t.tolerance, 0.004);
        break;
      case TaskVariable::x_p:
      case TaskVariable::y_p:
      case TaskVariable::xd_p:
      case TaskVariable::yd_p:
        EXPECT_EQ(t.value, 0.0);
        EXPECT_DOUBLE_EQ(t.tolerance, 0.004);
        break;
      case TaskVariable::w_x:
      case TaskVariable::w_y:
      case TaskVariable::w_z:
        EXPECT_EQ(t.value, 0.0);
        EXPECT_EQ(t.tolerance, 0.01);
        break;
      case TaskVariable::u_o:
      case TaskVariable::v_o:
        EXPECT_EQ(t.value, 0.0);
        EXPECT_DOUBLE_EQ(t.tolerance, M_PI / 18.0);
        break;
      default:
        ADD_FAILURE() << "unexpected target";
    }
  }
}

// docs/LEVELS.md's complete example is a level that loads, with every key.
TEST(LevelPack, TheDocumentedExampleLoads) {
  std::ifstream doc(std::string(HEMIROLL_SOURCE_DIR) + "/docs/LEVELS.md");
  std::string line, example;
  bool inside = false;
  while (std::getline(doc, line)) {
    if (!inside && line == "```lua") {
      inside = true;
    } else if (inside && line == "```") {
      break;
    } else if (inside) {
      example += line + "\n";
    }
  }
  ASSERT_FALSE(example.empty());
  const LevelDef d = LevelLoader(repositoryOptions()).loadSource(example, "example.lua").def;
  EXPECT_EQ(d.name, "Example");
  EXPECT_EQ(d.task.forbidden.size(), 1u);
  EXPECT_TRUE(d.task.failure.area.has_value());
  EXPECT_TRUE(d.scoring.hasMedals);
  EXPECT_TRUE(d.callbacks.onStart && d.callbacks.onUpdate && d.callbacks.onSuccess && d.callbacks.onFail);
}

TEST(LevelPack, TheRoseSceneIsWatchOnlyAndNamesItsBot) {
  const LevelDef d =
      LevelLoader(repositoryOptions()).loadFile(std::string(HEMIROLL_SOURCE_DIR) + "/levels/rose_demo.lua").def;
  EXPECT_TRUE(d.task.watchOnly());
  EXPECT_EQ(d.demoBot, "bots.rose");
  EXPECT_EQ(d.task.timeLimit, 35.0);  // the paper's Sec. 5 run
}

}  // namespace
}  // namespace hemiroll::script
