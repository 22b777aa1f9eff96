// game/ui/screens/TrialEnding: what decided a trial's time, in the player's
// words, and the medal thresholds, from crafted results.
#include "game/ui/screens/TrialEnding.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "engine/script/LevelLoader.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

task::TaskDef holdTask(double hold) {
  task::TaskDef task;
  task::StageDef stage;
  stage.hold = hold;
  task.stages.push_back(stage);
  return task;
}

task::ComponentStatus out(task::TaskVariable v, double error, double tolerance) {
  task::ComponentStatus c;
  c.variable = v;
  c.error = error;
  c.tolerance = tolerance;
  c.margin = tolerance - std::abs(error);
  c.inside = c.margin >= 0.0;
  return c;
}

TEST(TrialEndingTest, ASuccessNamesTheHoldThatEndedIt) {
  TrialResult r;
  r.outcome = task::TrialOutcome::Success;
  r.time = 12.34;
  r.summary.stageCount = 1;
  const std::vector<std::string> lines = explainEnding(r, holdTask(1.0));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "every band held for 1.0 s, from 11.34 s to 12.34 s");
  EXPECT_EQ(explainEnding(r, holdTask(0.0))[0], "inside every band at 12.34 s");
}

TEST(TrialEndingTest, AFailureNamesTheMomentAndTheFurthestOut) {
  TrialResult r;
  r.outcome = task::TrialOutcome::Failure;
  r.reason = "time limit reached";
  r.time = 240.0;
  r.summary.stageCount = 2;
  r.summary.stagesPassed = 1;
  using V = task::TaskVariable;
  r.summary.finalComponents = {out(V::u_a, 0.002, 0.004),  out(V::v_a, 0.012, 0.004), out(V::x_p, -0.009, 0.004),
                               out(V::y_p, 0.005, 0.004),  out(V::w_x, 0.02, 0.01),   out(V::w_y, 0.011, 0.01),
                               out(V::psi, 0.5, 0.17)};
  const std::vector<std::string> lines = explainEnding(r, holdTask(0.5));
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0], "at 240.00 s: time limit reached");
  EXPECT_EQ(lines[1], "1 of 2 stages passed");
  EXPECT_EQ(lines[2], "still out of its band at the end:");
  // Four groups are out (contact, heading, mass point, rolling); the three
  // furthest (by how many bands) are listed, worst first, in the player's
  // words: where to go on screen (the follow camera: +y is up), not the
  // physics' signed error.
  ASSERT_EQ(lines.size(), 7u);
  EXPECT_EQ(lines[3], "  contact point: roll 12.2 mm down (±4.0)");
  EXPECT_EQ(lines[4], "  heading: turn it 28.6 ° clockwise (±9.7)");
  EXPECT_EQ(lines[5], "  mass point: 10.3 mm off the face's middle, bring it back (±4.0)");
  EXPECT_EQ(lines[6], "  and 1 more");
}

TEST(TrialEndingTest, MedalThresholdsOnlyWhenTheLevelHasMedals) {
  task::ScoringDef s;
  EXPECT_EQ(medalLine(s, std::nullopt), "");
  s.hasMedals = true;
  s.bronze = 70;
  s.silver = 194;
  s.gold = 200;
  EXPECT_EQ(medalLine(s, std::nullopt), "bronze 70, silver 194, gold 200 points");
  EXPECT_EQ(medalLine(s, MedalTimes{170.0, 46.0, 40.0}), "gold in 40 s, silver 46 s, bronze 170 s");
}

// Where the score is a time, the thresholds are read as times by asking the
// level's own score function: the paper's task (240 s - time: 40, 46, 170 s
// as its comment says), tutorial 01 (floor(1000 (1 - t / 60)): 6, 12, 30 s)
// to the bisection's 0.01 s; the slalom's 800 for its eight gates plus a
// time bonus (a win: 45, 90, 180 s). A score that does not fall with time
// stays in points.
TEST(TrialEndingTest, MedalThresholdsAreTimesWhereTheScoreIsATime) {
  const auto timesOf = [](const char* file) {
    script::LoadedLevel level = script::LevelLoader().loadFile(std::string(HEMIROLL_SOURCE_DIR "/levels/") + file);
    return medalTimes(level);
  };
  const std::optional<MedalTimes> paper = timesOf("paper_reaching.lua");
  ASSERT_TRUE(paper.has_value());
  EXPECT_NEAR(paper->gold, 40.0, 0.01);
  EXPECT_NEAR(paper->silver, 46.0, 0.01);
  EXPECT_NEAR(paper->bronze, 170.0, 0.01);
  const std::optional<MedalTimes> tutorial = timesOf("tutorial_01_tilt_and_return.lua");
  ASSERT_TRUE(tutorial.has_value());
  EXPECT_NEAR(tutorial->gold, 6.0, 0.01);
  EXPECT_NEAR(tutorial->silver, 12.0, 0.01);
  EXPECT_NEAR(tutorial->bronze, 30.0, 0.01);
  const std::optional<MedalTimes> slalom = timesOf("challenge_slalom.lua");
  ASSERT_TRUE(slalom.has_value());
  EXPECT_NEAR(slalom->gold, 45.0, 0.01);
  EXPECT_NEAR(slalom->silver, 90.0, 0.01);
  EXPECT_NEAR(slalom->bronze, 180.0, 0.01);

  test::TempDirectory dir;
  for (const char* score : {"return s.success and 100 or 0", "return s.time"}) {
    const std::string file = dir.write("flat.lua", "return { name = 'flat', task = { targets = { u_a = { value = 0.001, "
                                                   "tol = 0.001 } } }, score = function(s) " +
                                                       std::string(score) +
                                                       " end, medals = { bronze = 1, silver = 2, gold = 3 } }");
    script::LoadedLevel level = script::LevelLoader().loadFile(file);
    EXPECT_FALSE(medalTimes(level).has_value()) << score;
  }
}

// What the loop's timing did, said on the results: the stops by name and
// time, and the stalls a mouse rode out (caught up, or the clock slowed).
TEST(TrialEndingTest, TheLoopsStopsAndStallsAreNamed) {
  LoopStory mouse;
  EXPECT_TRUE(explainLoop(mouse).empty());
  mouse.stalls = 3;
  mouse.worstLateness = 0.034;
  ASSERT_EQ(explainLoop(mouse).size(), 1u);
  EXPECT_EQ(explainLoop(mouse)[0], "the servo loop ran late 3 times (worst 34 ms): a mouse renders no force, so play "
                                   "went on and the loop caught up");
  mouse.slowedBy = 0.012;
  EXPECT_THAT(explainLoop(mouse)[0], ::testing::HasSubstr("the clock slowed by 12 ms in all"));
  LoopStory device;
  device.forceOutput = true;
  device.stalls = 1;  // a force device's stall is its stop
  device.stops.push_back({"servo loop stalled", 9.1});
  const std::vector<std::string> lines = explainLoop(device);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "safety stop at 9.10 s: servo loop stalled");
}

}  // namespace
}  // namespace hemiroll::game
