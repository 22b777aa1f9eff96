#pragma once
// Builds a TrialSummary tick by tick: path lengths, effort, smoothness and
// margins (definitions in TrialSummary.h). add() allocates nothing, so it may
// run beside TaskJudge::judge on the servo thread; summary() allocates.

#include "engine/physics/StateLayout.h"
#include "engine/task/TaskJudge.h"
#include "engine/task/TrialSummary.h"

namespace hemiroll::task {

// The per-tick inputs beyond the judge's.
struct EffortInput {
  physics::Vec3 proxyPosition = physics::Vec3::Zero();  // scene [m]
  physics::Vec3 handForce = physics::Vec3::Zero();      // F_h on the mass point [N]
};

class TrialSummaryAccumulator {
 public:
  void reset();
  // Call once per tick, after judge.judge(input) for the same tick.
  void add(const JudgeInput& input, const EffortInput& effort, const TaskJudge& judge);
  TrialSummary summary(const TaskJudge& judge) const;

 private:
  bool started_ = false;
  long long ticks_ = 0;
  double startTime_ = 0.0, lastTime_ = 0.0;
  double contactPath_ = 0.0, pointPath_ = 0.0;
  double lastU_ = 0.0, lastV_ = 0.0, lastX_ = 0.0, lastY_ = 0.0;
  double effort_ = 0.0, lastForceSquared_ = 0.0;
  physics::Vec3 proxyHistory_[3] = {physics::Vec3::Zero(), physics::Vec3::Zero(), physics::Vec3::Zero()};
  int proxySamples_ = 0;
  double jerkSquaredSum_ = 0.0;
  long long jerkSamples_ = 0;
  double bestMargin_ = -1e300;
};

}  // namespace hemiroll::task
