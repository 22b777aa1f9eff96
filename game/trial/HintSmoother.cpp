#include "game/trial/HintSmoother.h"

#include <algorithm>

#include "engine/autopilot/Autopilot.h"
#include "game/trial/AutopilotBot.h"
#include "game/trial/HumanBot.h"

namespace hemiroll::game {

void HintSmoother::reset(double radius) {
  radius_ = radius;
  technique_.reset();
  started_ = false;
  nextDecision_ = 0.0;
}

human::HintCue HintSmoother::cue(AutopilotBot& autopilot, const script::BotObservation& obs, double dt) {
  human::HintCue cue;
  if (!obs.targetSet[7] && !obs.targetSet[8]) return cue;
  if (!autopilot.giveUpReason().empty() || autopilot.autopilot() == nullptr) return cue;
  if (autopilot.autopilot()->stats().decisions == 0) return cue;
  if (!technique_) technique_.emplace(human::TechniqueDef{}, radius_);
  if (!started_ || obs.time >= nextDecision_) {
    const human::Movement::Kind was = movement_.kind;
    movement_ = technique_->decide(screenViewOf(obs), interval_);
    nextDecision_ = obs.time + interval_;
    if (!started_ || movement_.kind != was) centre_ = movement_.centre;  // a new kind of cue starts where it is
    started_ = true;
  }
  centre_ += std::min(1.0, dt / centreLag_) * (movement_.centre - centre_);
  if (movement_.kind == human::Movement::Kind::Hold) {
    cue.kind = human::HintKind::Settle;
    cue.point = centre_;
    return cue;
  }
  cue.kind = human::HintKind::Stir;
  cue.centre = centre_;
  cue.radius = movement_.radius;
  cue.rate = movement_.rate;
  return cue;
}

}  // namespace hemiroll::game
