// engine/task/TaskJudge: crafted states against declared tasks: the band's
// edge, the hold timer, stages, zones, domain events, the time limit.

#include "engine/task/TaskJudge.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/task/TrialSummaryAccumulator.h"
#include "tests/support/AllocationCounter.h"

namespace hemiroll::task {
namespace {

using physics::ForceDrivenState;
namespace slot = physics::force_slot;

TaskDef oneTarget(TaskVariable v, double value, double tolerance, double hold = 0.0) {
  TaskDef task;
  StageDef stage;
  stage.targets.push_back({v, value, tolerance});
  stage.hold = hold;
  task.stages.push_back(stage);
  return task;
}

JudgeInput at(double t, const ForceDrivenState& x = ForceDrivenState::Zero(),
              physics::DomainEvent event = physics::DomainEvent::None) {
  JudgeInput in;
  in.time = t;
  in.state = x;
  in.event = event;
  return in;
}

ForceDrivenState with(int s, double value) {
  ForceDrivenState x = ForceDrivenState::Zero();
  x[s] = value;
  return x;
}

TEST(TaskJudge, TheBandIncludesItsEdgeAndNothingBeyond) {
  // Target 0.01 +- 0.004: chosen so that 0.014 and 0.006 are the exact edges
  // up to rounding; the judge compares |error| <= tolerance, so test just
  // inside and just outside by one part in 1e9 of the tolerance.
  const double target = 0.01, tol = 0.004, eps = 4e-12;
  for (double value : {target + tol - eps, target - tol + eps}) {
    TaskJudge judge(oneTarget(TaskVariable::u_a, target, tol));
    EXPECT_EQ(judge.judge(at(0.0, with(slot::u_a, value))), TrialOutcome::Success) << value;
    EXPECT_GE(judge.components()[0].margin, 0.0);
  }
  for (double value : {target + tol + eps, target - tol - eps}) {
    TaskJudge judge(oneTarget(TaskVariable::u_a, target, tol));
    EXPECT_EQ(judge.judge(at(0.0, with(slot::u_a, value))), TrialOutcome::Running) << value;
    EXPECT_LT(judge.components()[0].margin, 0.0);
    EXPECT_FALSE(judge.components()[0].inside);
  }
}

TEST(TaskJudge, MarginAndErrorAreReported) {
  TaskJudge judge(oneTarget(TaskVariable::x_p, 0.002, 0.001, 10.0));
  judge.judge(at(0.0, with(slot::x_p, 0.0025)));
  ASSERT_EQ(judge.components().size(), 1u);
  const ComponentStatus& c = judge.components()[0];
  EXPECT_NEAR(c.error, 0.0005, 1e-15);      // rounding of the subtraction only
  EXPECT_NEAR(c.margin, 0.0005, 1e-15);
  EXPECT_NEAR(c.normalizedMargin(), 0.5, 1e-12);
  EXPECT_NEAR(judge.worstNormalizedMargin(), 0.5, 1e-12);
}

TEST(TaskJudge, HoldTimerRunsWhileInsideAndRestartsWhenLeft) {
  TaskJudge judge(oneTarget(TaskVariable::x_p, 0.0, 0.001, 0.5));
  const ForceDrivenState inside = ForceDrivenState::Zero();
  const ForceDrivenState outside = with(slot::x_p, 0.01);
  EXPECT_EQ(judge.judge(at(0.0, inside)), TrialOutcome::Running);
  EXPECT_EQ(judge.holdTime(), 0.0);
  EXPECT_EQ(judge.judge(at(0.3, inside)), TrialOutcome::Running);
  EXPECT_DOUBLE_EQ(judge.holdTime(), 0.3);
  EXPECT_EQ(judge.judge(at(0.4, outside)), TrialOutcome::Running);  // leaves: timer back to 0
  EXPECT_EQ(judge.holdTime(), 0.0);
  EXPECT_EQ(judge.judge(at(0.5, inside)), TrialOutcome::Running);
  EXPECT_EQ(judge.judge(at(0.9, inside)), TrialOutcome::Running);  // 0.4 s of 0.5
  EXPECT_EQ(judge.judge(at(1.0, inside)), TrialOutcome::Success);
  EXPECT_EQ(judge.reason(), trial_reason::kTargetHeld);
  EXPECT_EQ(judge.finishTime(), 1.0);
}

// The settle meter's source: which component broke the hold, when, by how
// much, and after how long a hold; none before the first hold.
TEST(TaskJudge, ABrokenHoldNamesTheComponentFurthestOut) {
  TaskDef task;
  StageDef stage;
  stage.targets.push_back({TaskVariable::u_a, 0.0, 0.001});
  stage.targets.push_back({TaskVariable::u_o, 0.0, 0.01});
  stage.hold = 1.0;
  task.stages.push_back(stage);
  TaskJudge judge(task);
  ForceDrivenState x = ForceDrivenState::Zero();
  x[slot::u_a] = 0.003;  // out before ever inside: no hold broken
  judge.judge(at(0.0, x));
  EXPECT_FALSE(judge.lastHoldBreak().happened);
  x[slot::u_a] = 0.0;
  judge.judge(at(0.1, x));
  judge.judge(at(0.4, x));
  // Both out: u_a by 0.5 of its band, u_o by twice its band: u_o is named.
  x[slot::u_a] = 0.0015;
  x[slot::u_o] = -0.03;
  judge.judge(at(0.5, x));
  const HoldBreak& b = judge.lastHoldBreak();
  ASSERT_TRUE(b.happened);
  EXPECT_EQ(b.variable, TaskVariable::u_o);
  EXPECT_EQ(b.time, 0.5);
  EXPECT_NEAR(b.excess, 0.02, 1e-15);
  EXPECT_NEAR(b.heldFor, 0.3, 1e-15);  // the hold as of the last inside tick
  // Staying out is not a second break.
  x[slot::u_o] = 0.0;
  judge.judge(at(0.6, x));
  EXPECT_EQ(judge.lastHoldBreak().time, 0.5);
  judge.reset();
  EXPECT_FALSE(judge.lastHoldBreak().happened);
}

TEST(TaskJudge, APreviewShowsTheComponentsAndJudgesNothing) {
  TaskJudge judge(oneTarget(TaskVariable::u_a, 0.01, 0.001, 0.5));
  judge.preview(with(slot::u_a, 0.0125));
  ASSERT_EQ(judge.components().size(), 1u);
  EXPECT_DOUBLE_EQ(judge.components()[0].error, 0.0025);
  EXPECT_FALSE(judge.allInside());
  judge.preview(with(slot::u_a, 0.01));
  EXPECT_TRUE(judge.allInside());
  EXPECT_EQ(judge.holdTime(), 0.0);  // no tick judged: no hold, no outcome
  EXPECT_EQ(judge.outcome(), TrialOutcome::Running);
  EXPECT_EQ(judge.judge(at(0.0, with(slot::u_a, 0.01))), TrialOutcome::Running);  // the hold starts with a tick
  EXPECT_EQ(judge.judge(at(0.5, with(slot::u_a, 0.01))), TrialOutcome::Success);
}

TEST(TaskJudge, HoldSurvivesTheRoundingOfSummedSteps) {
  // 500 steps of 1 ms summed in double land a hair below 0.5: still held.
  TaskJudge judge(oneTarget(TaskVariable::x_p, 0.0, 0.001, 0.5));
  double t = 0.0;
  int ticks = 0;
  while (judge.judge(at(t)) == TrialOutcome::Running && ticks < 1000) {
    t += 0.001;
    ++ticks;
  }
  EXPECT_EQ(ticks, 500);
}

TEST(TaskJudge, StagesAdvanceInOrderWithAFreshTimer) {
  TaskDef task;
  for (double x : {0.01, 0.02}) {
    StageDef stage;
    stage.targets.push_back({TaskVariable::u_a, x, 0.001});
    stage.hold = 0.1;
    task.stages.push_back(stage);
  }
  TaskJudge judge(task);
  EXPECT_EQ(judge.judge(at(0.0, with(slot::u_a, 0.02))), TrialOutcome::Running);  // stage 2's spot: no credit
  EXPECT_EQ(judge.stage(), 0);
  judge.judge(at(0.1, with(slot::u_a, 0.01)));
  judge.judge(at(0.2, with(slot::u_a, 0.01)));
  EXPECT_EQ(judge.stage(), 1);
  EXPECT_EQ(judge.stagesPassed(), 1);
  EXPECT_EQ(judge.holdTime(), 0.0);
  EXPECT_EQ(judge.components()[0].target, 0.02);
  judge.judge(at(0.3, with(slot::u_a, 0.02)));
  EXPECT_EQ(judge.judge(at(0.4, with(slot::u_a, 0.02))), TrialOutcome::Success);
  EXPECT_EQ(judge.stagesPassed(), 2);
}

TEST(TaskJudge, PsiIsComparedModuloTwoPi) {
  TaskJudge judge(oneTarget(TaskVariable::psi, 0.1, 0.01));
  EXPECT_EQ(judge.judge(at(0.0, with(slot::psi, 0.1 + 4.0 * M_PI))), TrialOutcome::Success);
  TaskJudge other(oneTarget(TaskVariable::psi, 0.1, 0.01));
  EXPECT_EQ(other.judge(at(0.0, with(slot::psi, 0.1 + M_PI))), TrialOutcome::Running);
  EXPECT_NEAR(std::abs(other.components()[0].error), M_PI, 1e-12);
}

TEST(TaskJudge, OmegaNormJudgesTheMagnitude) {
  ForceDrivenState x = ForceDrivenState::Zero();
  x[slot::w_x] = 0.006;
  x[slot::w_y] = 0.008;  // |omega| = 0.01
  TaskJudge judge(oneTarget(TaskVariable::omega_norm, 0.0, 0.0101));
  EXPECT_EQ(judge.judge(at(0.0, x)), TrialOutcome::Success);
  TaskJudge tight(oneTarget(TaskVariable::omega_norm, 0.0, 0.0099));
  EXPECT_EQ(tight.judge(at(0.0, x)), TrialOutcome::Running);
}

TEST(TaskJudge, ForbiddenCircleAndBoxFailOnEntryNotOnTheEdge) {
  TaskDef task = oneTarget(TaskVariable::x_p, 1.0, 0.001);
  ZoneDef circle;
  circle.center = {0.05, 0.0};
  circle.radius = 0.01;
  ZoneDef box;
  box.shape = ZoneShape::Box;
  box.min = {-0.02, 0.01};
  box.max = {0.0, 0.03};
  task.forbidden = {circle, box};
  {
    TaskJudge judge(task);
    ForceDrivenState x = with(slot::u_a, 0.04);  // on the circle's edge
    EXPECT_EQ(judge.judge(at(0.0, x)), TrialOutcome::Running);
    x[slot::u_a] = 0.0401;
    EXPECT_EQ(judge.judge(at(0.1, x)), TrialOutcome::Failure);
    EXPECT_EQ(judge.reason(), trial_reason::kForbiddenZone);
    EXPECT_EQ(judge.forbiddenZoneHit(), 0);
  }
  {
    TaskJudge judge(task);
    ForceDrivenState x = ForceDrivenState::Zero();
    x[slot::u_a] = -0.01;
    x[slot::v_a] = 0.01;  // on the box's lower edge
    EXPECT_EQ(judge.judge(at(0.0, x)), TrialOutcome::Running);
    x[slot::v_a] = 0.011;
    EXPECT_EQ(judge.judge(at(0.1, x)), TrialOutcome::Failure);
    EXPECT_EQ(judge.forbiddenZoneHit(), 1);
  }
}

TEST(TaskJudge, LeavingTheAreaFails) {
  TaskDef task = oneTarget(TaskVariable::x_p, 1.0, 0.001);
  ZoneDef area;
  area.radius = 0.1;
  task.failure.area = area;
  TaskJudge judge(task);
  EXPECT_EQ(judge.judge(at(0.0, with(slot::v_a, 0.1))), TrialOutcome::Running);  // the edge is inside
  EXPECT_EQ(judge.judge(at(0.1, with(slot::v_a, 0.1001))), TrialOutcome::Failure);
  EXPECT_EQ(judge.reason(), trial_reason::kLeftArea);
}

TEST(TaskJudge, DomainEventsFailWhenTheLevelSaysSo) {
  TaskJudge judge(oneTarget(TaskVariable::x_p, 0.0, 1.0, 5.0));
  EXPECT_EQ(judge.judge(at(0.1, ForceDrivenState::Zero(), physics::DomainEvent::TippedOver)), TrialOutcome::Failure);
  EXPECT_EQ(judge.reason(), trial_reason::kTippedOver);

  TaskDef lenient = oneTarget(TaskVariable::x_p, 0.0, 1.0, 5.0);
  lenient.failure.tipOver = false;
  TaskJudge ignoring(lenient);
  EXPECT_EQ(ignoring.judge(at(0.1, ForceDrivenState::Zero(), physics::DomainEvent::TippedOver)), TrialOutcome::Running);
  EXPECT_EQ(ignoring.judge(at(0.2, ForceDrivenState::Zero(), physics::DomainEvent::LeftFace)), TrialOutcome::Failure);
  EXPECT_EQ(ignoring.reason(), trial_reason::kLeftFace);
}

TEST(TaskJudge, NonFiniteStateAlwaysFails) {
  TaskDef task = oneTarget(TaskVariable::x_p, 0.0, 1.0);
  task.failure.tipOver = task.failure.offFace = false;
  TaskJudge judge(task);
  EXPECT_EQ(judge.judge(at(0.0, with(slot::w_z, std::numeric_limits<double>::quiet_NaN()))), TrialOutcome::Failure);
  EXPECT_EQ(judge.reason(), trial_reason::kNonFinite);
}

TEST(TaskJudge, TimeLimitFailsButAHoldOnTheLastTickCounts) {
  TaskDef task = oneTarget(TaskVariable::x_p, 0.0, 0.001);
  task.timeLimit = 2.0;
  TaskJudge late(task);
  EXPECT_EQ(late.judge(at(1.999, with(slot::x_p, 1.0))), TrialOutcome::Running);
  EXPECT_EQ(late.judge(at(2.0, with(slot::x_p, 1.0))), TrialOutcome::Failure);
  EXPECT_EQ(late.reason(), trial_reason::kTimeLimit);
  TaskJudge justInTime(task);
  EXPECT_EQ(justInTime.judge(at(2.0)), TrialOutcome::Success);
}

// 60000 steps of 1 ms sum to just under 60 s: the limit is reached on the
// 60000th tick, not one tick later (a 60 s level ended at 60.001 s while a
// 120 s one ended at 120.000).
TEST(TaskJudge, TheTimeLimitEndsOnItsOwnTickWhateverTheSumsRounding) {
  TaskDef task = oneTarget(TaskVariable::x_p, 0.0, 0.001);
  for (const double limit : {60.0, 120.0, 0.3}) {
    task.timeLimit = limit;
    TaskJudge judge(task);
    double t = 0.0;
    long long ticks = 0;
    while (judge.judge(at(t, with(slot::x_p, 1.0))) == TrialOutcome::Running && ticks < 200000) {
      t += 0.001;
      ++ticks;
    }
    EXPECT_EQ(ticks, std::llround(limit / 0.001)) << limit;
    EXPECT_EQ(judge.reason(), trial_reason::kTimeLimit);
  }
}

TEST(TaskJudge, WatchOnlyLevelsSucceedAtTheTimeLimit) {
  TaskDef task;
  task.timeLimit = 1.0;
  TaskJudge judge(task);
  EXPECT_EQ(judge.judge(at(0.5)), TrialOutcome::Running);
  EXPECT_EQ(judge.judge(at(1.0)), TrialOutcome::Success);
  EXPECT_EQ(judge.reason(), trial_reason::kWatched);
}

TEST(TaskJudge, AFinishedTrialStaysFinished) {
  TaskJudge judge(oneTarget(TaskVariable::x_p, 0.0, 0.001));
  judge.judge(at(0.0, ForceDrivenState::Zero(), physics::DomainEvent::LeftFace));
  EXPECT_EQ(judge.judge(at(0.1)), TrialOutcome::Failure);  // inside now, but over
  judge.finish(TrialOutcome::Success, "late", 0.2);
  EXPECT_EQ(judge.outcome(), TrialOutcome::Failure);
  EXPECT_EQ(judge.reason(), trial_reason::kLeftFace);
}

TEST(TaskJudge, DynamicTargetsMoveTheBandAndRestartTheHold) {
  TaskJudge judge(oneTarget(TaskVariable::x_p, 0.0, 0.001, 1.0));
  judge.judge(at(0.0));
  judge.judge(at(0.5));
  EXPECT_EQ(judge.holdTime(), 0.5);
  EXPECT_EQ(judge.setTarget(0, TaskVariable::x_p, 0.005, 0.001), "");
  EXPECT_EQ(judge.holdTime(), 0.0);
  EXPECT_EQ(judge.judge(at(0.6)), TrialOutcome::Running);
  EXPECT_FALSE(judge.allInside());
  EXPECT_EQ(judge.setTarget(0, TaskVariable::y_p, 0.0, 0.01), "");  // added
  EXPECT_EQ(judge.components().size(), 2u);
  EXPECT_NE(judge.setTarget(0, TaskVariable::y_p, 0.0, 0.0), "");
  EXPECT_NE(judge.setTarget(3, TaskVariable::y_p, 0.0, 1.0), "");
  judge.removeTarget(0, TaskVariable::x_p);
  EXPECT_EQ(judge.judge(at(0.7)), TrialOutcome::Running);
  EXPECT_TRUE(judge.allInside());
  judge.reset();  // back to the declared task
  EXPECT_EQ(judge.components().size(), 1u);
  EXPECT_EQ(judge.components()[0].target, 0.0);
}

TEST(TaskJudge, SlotTargetsListTheCurrentStage) {
  TaskDef task = oneTarget(TaskVariable::v_a, -0.04, 0.004);
  task.stages[0].targets.push_back({TaskVariable::omega_norm, 0.0, 0.01});  // not a slot
  TaskJudge judge(task);
  std::array<double, 12> value{}, tolerance{};
  std::array<bool, 12> set{};
  judge.slotTargets(value, tolerance, set);
  for (int i = 0; i < 12; ++i) EXPECT_EQ(set[static_cast<std::size_t>(i)], i == slot::v_a) << i;
  EXPECT_EQ(value[slot::v_a], -0.04);
  EXPECT_EQ(tolerance[slot::v_a], 0.004);
}

TEST(TaskJudge, JudgingATickAllocatesNothing) {
  // Stages, zones, an area, the hold timer running and resetting, a stage
  // passed and success: every path of judge() and of the summary's add().
  TaskDef task;
  for (double x : {0.001, 0.002}) {
    StageDef stage;
    stage.targets.push_back({TaskVariable::u_a, x, 0.0005});
    stage.targets.push_back({TaskVariable::omega_norm, 0.0, 1.0});
    stage.targets.push_back({TaskVariable::psi, 0.0, 1.0});
    stage.hold = 0.05;
    task.stages.push_back(stage);
  }
  ZoneDef pit;
  pit.center = {0.5, 0.5};
  pit.radius = 0.01;
  task.forbidden = {pit, pit};
  ZoneDef area;
  area.shape = ZoneShape::Box;
  area.min = {-1, -1};
  area.max = {1, 1};
  task.failure.area = area;
  TaskJudge judge(task);
  TrialSummaryAccumulator summary;
  ASSERT_TRUE(test::allocationCounterWorks());
  test::AllocationCounter counter;
  JudgeInput in;
  EffortInput effort;
  for (int tick = 0; tick < 400 && !judge.finished(); ++tick) {
    in.time = tick * 0.001;
    in.state[slot::u_a] = 0.00001 * tick;  // through stage 1's band, then stage 2's
    effort.proxyPosition.x() = in.state[slot::u_a];
    judge.judge(in);
    summary.add(in, effort, judge);
  }
  EXPECT_EQ(counter.count(), 0);
  EXPECT_EQ(judge.outcome(), TrialOutcome::Success);  // every path was taken
  EXPECT_EQ(judge.stagesPassed(), 2);
}

}  // namespace
}  // namespace hemiroll::task
