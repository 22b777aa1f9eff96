#include "game/play/RingJudge.h"

#include <algorithm>

namespace hemiroll::game {

using script::TrialOutcome;

namespace {

physics::Vec3 vec(const std::array<double, 3>& t) { return {t[0], t[1], t[2]}; }

}  // namespace

RingJudge::RingJudge(script::LoadedLevel& level, haptics::RecordRing* forward, int forwardEvery, bool faultsEndTrial)
    : level_(level),
      forward_(forward),
      forwardEvery_(std::max(1, forwardEvery)),
      faultsEndTrial_(faultsEndTrial),
      judge_(level.def.task) {}

void RingJudge::start(const physics::ForceDrivenState& initial) {
  view_.state = initial;
  level_.script->start(view_, judge_);
  if (judge_.finished()) level_.script->update(view_, judge_);  // on_fail for a trial failed at once
}

std::size_t RingJudge::drain(haptics::RecordRing& ring) {
  script::LevelScript& levelScript = *level_.script;
  haptics::RecordRow row;
  std::size_t judged = 0;
  while (!judge_.finished() && ring.pop(row)) {
    script::JudgeInput input;
    input.time = row.time;
    input.state = Eigen::Map<const physics::ForceDrivenState>(row.state.data());
    input.event = row.event;
    judge_.judge(input);
    script::EffortInput effort;
    effort.proxyPosition = vec(row.proxyPosition);
    effort.handForce = vec(row.handForce);
    accumulator_.add(input, effort, judge_);
    maxRenderedForce_ = std::max(maxRenderedForce_, vec(row.renderedForce).norm());
    maxProxyDistance_ = std::max(maxProxyDistance_, row.proxyDistance);
    if (faultsEndTrial_ && !judge_.finished() && row.fault != haptics::SafetyFault::None)
      judge_.finish(TrialOutcome::Failure, std::string("safety: ") + haptics::safetyFaultName(row.fault), row.time);
    if (forward_ != nullptr && row.tick % static_cast<std::uint64_t>(forwardEvery_) == 0) forward_->push(row);
    view_.time = row.time;
    view_.state = input.state;
    view_.proxy = effort.proxyPosition;
    view_.handForce = effort.handForce;
    levelScript.update(view_, judge_);
    judgedTicks_ = static_cast<long long>(row.tick);
    ++judged;
  }
  return judged;
}

void RingJudge::fail(const std::string& reason) {
  if (judge_.finished()) return;
  judge_.finish(TrialOutcome::Failure, reason, view_.time);
  level_.script->update(view_, judge_);  // on_fail
}

TrialResult RingJudge::result(const physics::ForceDrivenState& initial) {
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
  result.finalState = judgedTicks_ == 0 ? initial : view_.state;
  result.maxRenderedForce = maxRenderedForce_;
  result.maxProxyDistance = maxProxyDistance_;
  return result;
}

}  // namespace hemiroll::game
