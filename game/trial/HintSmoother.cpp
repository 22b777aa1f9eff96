#include "game/trial/HintSmoother.h"

#include <algorithm>

#include "engine/autopilot/Autopilot.h"
#include "engine/physics/PlaneVectors.h"
#include "engine/physics/StateKinematics.h"
#include "game/trial/AutopilotBot.h"
#include "game/trial/HumanBot.h"

namespace hemiroll::game {

void HintSmoother::reset(double radius) {
  radius_ = radius;
  technique_.reset();
  started_ = false;
  watching_ = false;
  uprightVelocity_ = physics::Vec2::Zero();
  nextDecision_ = 0.0;
}

void HintSmoother::watchUpright(const script::BotObservation& obs, double dt) {
  human::ScreenView view;
  view.contact = physics::Vec2(obs.contact[0], obs.contact[1]);
  view.normal = physics::vec3Of(obs.normal);
  const physics::Vec2 upright = human::uprightContactSeen(view, radius_);
  if (watching_ && dt > 0.0)
    uprightVelocity_ += std::min(1.0, dt / def_.leadWatch) * ((upright - upright_) / dt - uprightVelocity_);
  watching_ = true;
  upright_ = upright;
}

human::HintCue HintSmoother::cue(AutopilotBot& autopilot, const script::BotObservation& obs, double dt) {
  const bool planned = autopilot.giveUpReason().empty() && autopilot.autopilot() != nullptr &&
                       autopilot.autopilot()->stats().decisions > 0;
  return cue(obs, dt, planned);
}

human::HintCue HintSmoother::cue(const script::BotObservation& obs, double dt, bool planned) {
  watchUpright(obs, dt);
  human::HintCue cue;
  if (!obs.targetSet[7] && !obs.targetSet[8]) return cue;
  if (!planned) return cue;
  if (!technique_) technique_.emplace(human::TechniqueDef{}, radius_);
  if (!started_ || obs.time >= nextDecision_) {
    const human::Movement::Kind was = movement_.kind;
    movement_ = technique_->decide(screenViewOf(obs), def_.interval);
    nextDecision_ = obs.time + def_.interval;
    if (!started_ || movement_.kind != was) centre_ = movement_.centre;  // a new kind of cue starts where it is
    started_ = true;
  }
  centre_ += std::min(1.0, dt / def_.centreLag) * (movement_.centre - centre_);
  const physics::Vec2 shown = centre_ + physics::limitedTo(def_.lead * uprightVelocity_, def_.leadLimit);
  if (movement_.kind == human::Movement::Kind::Hold) {
    cue.kind = human::HintKind::Settle;
    cue.point = shown;
    return cue;
  }
  cue.kind = human::HintKind::Stir;
  cue.centre = shown;
  cue.radius = movement_.radius;
  cue.rate = movement_.rate;
  return cue;
}

}  // namespace hemiroll::game
