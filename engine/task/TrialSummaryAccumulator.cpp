#include "engine/task/TrialSummaryAccumulator.h"

#include <cmath>
#include <limits>

namespace hemiroll::task {

void TrialSummaryAccumulator::reset() { *this = TrialSummaryAccumulator(); }

void TrialSummaryAccumulator::add(const JudgeInput& input, const EffortInput& effort, const TaskJudge& judge) {
  using namespace physics::force_slot;
  const physics::ForceDrivenState& x = input.state;
  const double t = input.time;
  const double forceSquared = effort.handForce.squaredNorm();
  // A non-finite tick (the judge fails the trial on it) would poison every
  // sum; the summary keeps what was finite.
  if (!x.allFinite() || !std::isfinite(t) || !std::isfinite(forceSquared) || !effort.proxyPosition.allFinite())
    return;
  ++ticks_;
  if (!started_) {
    started_ = true;
    startTime_ = t;
  } else {
    const double dt = t - lastTime_;
    contactPath_ += std::hypot(x[u_a] - lastU_, x[v_a] - lastV_);
    pointPath_ += std::hypot(x[x_p] - lastX_, x[y_p] - lastY_);
    effort_ += 0.5 * (forceSquared + lastForceSquared_) * dt;
    // Third backward difference of the proxy over equal ticks: the jerk.
    if (proxySamples_ >= 3 && dt > 0.0) {
      const physics::Vec3 jerk =
          (effort.proxyPosition - 3.0 * proxyHistory_[0] + 3.0 * proxyHistory_[1] - proxyHistory_[2]) /
          (dt * dt * dt);
      jerkSquaredSum_ += jerk.squaredNorm();
      ++jerkSamples_;
    }
  }
  lastTime_ = t;
  lastU_ = x[u_a];
  lastV_ = x[v_a];
  lastX_ = x[x_p];
  lastY_ = x[y_p];
  lastForceSquared_ = forceSquared;
  proxyHistory_[2] = proxyHistory_[1];
  proxyHistory_[1] = proxyHistory_[0];
  proxyHistory_[0] = effort.proxyPosition;
  if (proxySamples_ < 3) ++proxySamples_;
  const double worst = judge.worstNormalizedMargin();
  if (std::isfinite(worst) && worst > bestMargin_) bestMargin_ = worst;
}

TrialSummary TrialSummaryAccumulator::summary(const TaskJudge& judge) const {
  TrialSummary s;
  s.outcome = judge.outcome();
  s.reason = std::string(judge.reason());
  s.time = judge.finished() ? judge.finishTime() : lastTime_;
  s.ticks = ticks_;
  s.stagesPassed = judge.stagesPassed();
  s.stageCount = judge.stageCount();
  s.stageTimes = judge.stagePassTimes();
  s.contactPath = contactPath_;
  s.pointPath = pointPath_;
  s.effort = effort_;
  s.smoothness = jerkSamples_ > 0 ? jerkSquaredSum_ / static_cast<double>(jerkSamples_) : 0.0;
  // A task with nothing to judge (watch-only) has no margins: report 1, "on target", rather than an infinity Lua would print
  // as "inf".
  const double worst = judge.worstNormalizedMargin();
  s.finalMargin = std::isfinite(worst) ? worst : 1.0;
  s.bestMargin = bestMargin_ > -1e300 ? bestMargin_ : s.finalMargin;
  s.finalComponents.assign(judge.components().begin(), judge.components().end());
  return s;
}

}  // namespace hemiroll::task
