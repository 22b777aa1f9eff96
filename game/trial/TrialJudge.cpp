#include "game/trial/TrialJudge.h"

#include <algorithm>

#include "engine/physics/StateKinematics.h"

namespace hemiroll::game {

using task::TrialOutcome;

TrialJudge::TrialJudge(script::LoadedLevel& level, bool faultsEndTrial)
    : level_(level), faultsEndTrial_(faultsEndTrial), judge_(level.def.task) {}

void TrialJudge::start(const physics::ForceDrivenState& initial) {
  view_.state = initial;
  judge_.preview(initial);  // the components as they start, before any tick
  level_.script->start(view_, judge_);
  if (judge_.finished()) level_.script->update(view_, judge_);  // on_fail for a trial failed at once
}

// ServoSnapshot and RecordRow carry the same fields under the same names.
template <class Tick>
void TrialJudge::judgeAny(const Tick& tick) {
  if (judge_.finished()) return;
  task::JudgeInput input;
  input.time = tick.time;
  input.state = physics::forceStateOf(tick.state);
  input.event = tick.event;
  judge_.judge(input);
  task::EffortInput effort;
  effort.proxyPosition = physics::vec3Of(tick.proxyPosition);
  effort.handForce = physics::vec3Of(tick.handForce);
  accumulator_.add(input, effort, judge_);
  maxRenderedForce_ = std::max(maxRenderedForce_, physics::vec3Of(tick.renderedForce).norm());
  maxProxyDistance_ = std::max(maxProxyDistance_, tick.proxyDistance);
  if (faultsEndTrial_ && !judge_.finished() && tick.fault != haptics::SafetyFault::None)
    judge_.finish(TrialOutcome::Failure, std::string("safety: ") + haptics::safetyFaultName(tick.fault), tick.time);
  view_.time = tick.time;
  view_.state = input.state;
  view_.proxy = effort.proxyPosition;
  view_.handForce = effort.handForce;
  level_.script->update(view_, judge_);
  judgedTicks_ = static_cast<long long>(tick.tick);
}

void TrialJudge::judgeTick(const haptics::ServoSnapshot& tick) { judgeAny(tick); }
void TrialJudge::judgeTick(const haptics::RecordRow& tick) { judgeAny(tick); }

void TrialJudge::fail(const std::string& reason) {
  if (judge_.finished()) return;
  judge_.finish(TrialOutcome::Failure, reason, view_.time);
  level_.script->update(view_, judge_);  // on_fail
}

TrialResult TrialJudge::result(const physics::ForceDrivenState& initial) {
  TrialResult result;
  result.outcome = judge_.outcome();
  result.reason = std::string(judge_.reason());
  result.time = judge_.finishTime();
  result.ticks = judgedTicks_;
  result.summary = accumulator_.summary(judge_);
  const script::ScoreResult score = level_.script->score(result.summary);
  result.score = score.score;
  result.medal = score.medal;
  result.scoreError = score.error;
  result.endCallbackError = level_.script->endCallbackError();
  result.finalState = judgedTicks_ == 0 ? initial : view_.state;
  result.maxRenderedForce = maxRenderedForce_;
  result.maxProxyDistance = maxProxyDistance_;
  return result;
}

}  // namespace hemiroll::game
