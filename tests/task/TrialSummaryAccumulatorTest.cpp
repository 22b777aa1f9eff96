// engine/task/TrialSummaryAccumulator: path lengths, effort, smoothness
// and margins on crafted tick sequences whose values follow by hand.

#include "engine/task/TrialSummaryAccumulator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace hemiroll::task {
namespace {

namespace slot = physics::force_slot;

TaskDef farTarget() {
  TaskDef task;
  StageDef stage;
  stage.targets.push_back({TaskVariable::x_p, 0.0, 0.01});
  task.stages.push_back(stage);
  task.timeLimit = 100.0;
  return task;
}

struct Tick {
  double t;
  double u, v, x;      // contact point, mass point x
  physics::Vec3 proxy;
  physics::Vec3 force;
};

// Eigen's default constructor leaves a vector uninitialized, so `{}` is no zero.
const physics::Vec3 kZero = physics::Vec3::Zero();

void feed(TaskJudge& judge, TrialSummaryAccumulator& acc, const Tick& tick) {
  JudgeInput in;
  in.time = tick.t;
  in.state[slot::u_a] = tick.u;
  in.state[slot::v_a] = tick.v;
  in.state[slot::x_p] = tick.x;
  judge.judge(in);
  EffortInput effort;
  effort.proxyPosition = tick.proxy;
  effort.handForce = tick.force;
  acc.add(in, effort, judge);
}

TEST(TrialSummaryAccumulator, PathLengthsSumTheSegments) {
  // Contact point along a 3-4-5 triangle's legs, then back along the
  // hypotenuse: 3 + 4 + 5 mm.
  TaskJudge judge(farTarget());
  TrialSummaryAccumulator acc;
  const double mm = 0.001;
  feed(judge, acc, {0.0, 0, 0, 0.02, kZero, kZero});
  feed(judge, acc, {0.1, 3 * mm, 0, 0.02, kZero, kZero});
  feed(judge, acc, {0.2, 3 * mm, 4 * mm, 0.025, kZero, kZero});
  feed(judge, acc, {0.3, 0, 0, 0.02, kZero, kZero});
  const TrialSummary s = acc.summary(judge);
  EXPECT_NEAR(s.contactPath, 12 * mm, 1e-15);  // rounding of three hypot calls
  EXPECT_NEAR(s.pointPath, 10 * mm, 1e-15);    // x_p: 0.02 -> 0.025 -> 0.02
  EXPECT_EQ(s.ticks, 4);
  EXPECT_EQ(s.time, 0.3);
  EXPECT_EQ(s.outcome, TrialOutcome::Running);
}

TEST(TrialSummaryAccumulator, EffortIsTheIntegralOfTheSquaredForce) {
  // |F| = 2 N for 1 s in 1 ms ticks: 4 N^2 s (the trapezoid is exact for a constant).
  TaskJudge judge(farTarget());
  TrialSummaryAccumulator acc;
  for (int i = 0; i <= 1000; ++i) feed(judge, acc, {i * 0.001, 0, 0, 0.1, kZero, physics::Vec3(0, 1.2, 1.6)});
  EXPECT_NEAR(acc.summary(judge).effort, 4.0, 1e-9);  // 1000 additions of 0.004
}

TEST(TrialSummaryAccumulator, SmoothnessIsTheMeanSquaredProxyJerk) {
  // x = t^3: the third difference is exactly 6 dt^3, so |j|^2 = 36 on every
  // tick from the fourth on (up to rounding of t^3).
  TaskJudge judge(farTarget());
  TrialSummaryAccumulator acc;
  const double dt = 0.01;
  for (int i = 0; i <= 100; ++i) {
    const double t = i * dt;
    feed(judge, acc, {t, 0, 0, 0.1, physics::Vec3(t * t * t, 0, 0), kZero});
  }
  EXPECT_NEAR(acc.summary(judge).smoothness, 36.0, 1e-3);
  // A proxy moving at constant velocity has no jerk at all.
  TaskJudge judge2(farTarget());
  TrialSummaryAccumulator steady;
  for (int i = 0; i <= 100; ++i) feed(judge2, steady, {i * dt, 0, 0, 0.1, physics::Vec3(0.5 * i * dt, 0, 0), kZero});
  EXPECT_LT(steady.summary(judge2).smoothness, 1e-12);
}

TEST(TrialSummaryAccumulator, MarginsTrackTheBestApproachAndTheEnd) {
  TaskJudge judge(farTarget());  // x_p = 0 +- 0.01
  TrialSummaryAccumulator acc;
  feed(judge, acc, {0.0, 0, 0, 0.05, kZero, kZero});   // normalized margin (0.01 - 0.05)/0.01 = -4
  feed(judge, acc, {0.1, 0, 0, 0.015, kZero, kZero});  // -0.5: the best
  feed(judge, acc, {0.2, 0, 0, 0.03, kZero, kZero});   // -2
  const TrialSummary s = acc.summary(judge);
  EXPECT_NEAR(s.bestMargin, -0.5, 1e-12);
  EXPECT_NEAR(s.finalMargin, -2.0, 1e-12);
  ASSERT_EQ(s.finalComponents.size(), 1u);
  EXPECT_NEAR(s.finalComponents[0].error, 0.03, 1e-15);
}

TEST(TrialSummaryAccumulator, SuccessKeepsTheLastStagesComponents) {
  TaskJudge judge(farTarget());
  TrialSummaryAccumulator acc;
  feed(judge, acc, {0.0, 0, 0, 0.005, kZero, kZero});
  const TrialSummary s = acc.summary(judge);
  EXPECT_EQ(s.outcome, TrialOutcome::Success);
  EXPECT_EQ(s.reason, trial_reason::kTargetHeld);
  EXPECT_EQ(s.stagesPassed, 1);
  ASSERT_EQ(s.finalComponents.size(), 1u);
  EXPECT_NEAR(s.finalMargin, 0.5, 1e-12);
}

TEST(TrialSummaryAccumulator, NonFiniteTicksAreLeftOut) {
  TaskJudge judge(farTarget());
  TrialSummaryAccumulator acc;
  feed(judge, acc, {0.0, 0, 0, 0.02, kZero, physics::Vec3(1, 0, 0)});
  feed(judge, acc, {0.1, std::numeric_limits<double>::quiet_NaN(), 0, 0.02, kZero, physics::Vec3(1, 0, 0)});
  const TrialSummary s = acc.summary(judge);
  EXPECT_TRUE(std::isfinite(s.contactPath));
  EXPECT_TRUE(std::isfinite(s.effort));
  EXPECT_EQ(s.ticks, 1);
  EXPECT_EQ(s.reason, trial_reason::kNonFinite);
}

TEST(TrialSummaryAccumulator, WatchOnlyTasksReportFullMargins) {
  TaskDef task;
  task.timeLimit = 1.0;
  TaskJudge judge(task);
  TrialSummaryAccumulator acc;
  feed(judge, acc, {0.0, 0, 0, 0.0, kZero, kZero});
  EXPECT_EQ(acc.summary(judge).finalMargin, 1.0);
  EXPECT_EQ(acc.summary(judge).bestMargin, 1.0);
}

}  // namespace
}  // namespace hemiroll::task
