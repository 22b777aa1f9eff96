// game/screens/TrialEnding: what decided a trial's time, in the player's
// words, and the medal thresholds, from crafted results.
#include "game/screens/TrialEnding.h"

#include <gtest/gtest.h>

namespace hemiroll::game {
namespace {

script::TaskDef holdTask(double hold) {
  script::TaskDef task;
  script::StageDef stage;
  stage.hold = hold;
  task.stages.push_back(stage);
  return task;
}

script::ComponentStatus out(script::TaskVariable v, double error, double tolerance) {
  script::ComponentStatus c;
  c.variable = v;
  c.error = error;
  c.tolerance = tolerance;
  c.margin = tolerance - std::abs(error);
  c.inside = c.margin >= 0.0;
  return c;
}

TEST(TrialEndingTest, ASuccessNamesTheHoldThatEndedIt) {
  TrialResult r;
  r.outcome = script::TrialOutcome::Success;
  r.time = 12.34;
  r.summary.stageCount = 1;
  const std::vector<std::string> lines = explainEnding(r, holdTask(1.0));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "every band held for 1.0 s, from 11.34 s to 12.34 s");
  EXPECT_EQ(explainEnding(r, holdTask(0.0))[0], "inside every band at 12.34 s");
}

TEST(TrialEndingTest, AFailureNamesTheMomentAndTheFurthestOut) {
  TrialResult r;
  r.outcome = script::TrialOutcome::Failure;
  r.reason = "time limit reached";
  r.time = 240.0;
  r.summary.stageCount = 2;
  r.summary.stagesPassed = 1;
  using V = script::TaskVariable;
  r.summary.finalComponents = {out(V::u_a, 0.002, 0.004),  out(V::v_a, 0.012, 0.004), out(V::x_p, -0.009, 0.004),
                               out(V::y_p, 0.005, 0.004),  out(V::w_x, 0.02, 0.01),   out(V::w_y, 0.011, 0.01),
                               out(V::psi, 0.5, 0.17)};
  const std::vector<std::string> lines = explainEnding(r, holdTask(0.5));
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0], "at 240.00 s: time limit reached");
  EXPECT_EQ(lines[1], "1 of 2 stages passed");
  EXPECT_EQ(lines[2], "furthest out of its band at the end:");
  // Six are out; the four furthest (by how many bands) are listed, worst first.
  ASSERT_EQ(lines.size(), 8u);
  EXPECT_EQ(lines[3], "  contact y off by +12.0 mm (band ±4.0 mm)");
  EXPECT_EQ(lines[4], "  heading off by +28.6 ° (band ±9.7 °)");
  EXPECT_EQ(lines[5], "  mass point x off by -9.0 mm (band ±4.0 mm)");
  EXPECT_EQ(lines[6], "  spin x off by +1.15 °/s (band ±0.57 °/s)");
  EXPECT_EQ(lines[7], "  and 2 more");
}

TEST(TrialEndingTest, MedalThresholdsOnlyWhenTheLevelHasMedals) {
  script::ScoringDef s;
  EXPECT_EQ(medalThresholds(s), "");
  s.hasMedals = true;
  s.bronze = 70;
  s.silver = 194;
  s.gold = 200;
  EXPECT_EQ(medalThresholds(s), "bronze 70, silver 194, gold 200 points");
}

}  // namespace
}  // namespace hemiroll::game
