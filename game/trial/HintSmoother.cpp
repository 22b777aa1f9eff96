#include "game/trial/HintSmoother.h"

#include "engine/autopilot/Autopilot.h"
#include "game/trial/AutopilotBot.h"

namespace hemiroll::game {

human::HintCue HintSmoother::cue(AutopilotBot& autopilot, const script::BotObservation& obs, double dt) {
  human::HintCue cue;
  if (!obs.targetSet[7] && !obs.targetSet[8]) return cue;
  if (!autopilot.giveUpReason().empty() || autopilot.autopilot() == nullptr) return cue;
  if (autopilot.autopilot()->stats().decisions == 0) return cue;
  const autopilot::HelixMotion& m = autopilot.autopilot()->policy().motion();
  const bool settling = m.phase == autopilot::HelixPhase::Settle;
  const physics::Vec2 wanted = settling ? m.goal : m.centre;
  if (!started_ || settling != settling_) {
    centre_ = wanted;
    started_ = true;
    settling_ = settling;
  }
  centre_ += (dt / centreLag_) * (wanted - centre_);
  if (settling) {
    cue.kind = human::HintKind::Settle;
    cue.point = centre_;
    return cue;
  }
  cue.kind = human::HintKind::Stir;
  cue.centre = centre_;
  cue.radius = m.radius;
  cue.rate = m.rate;
  return cue;
}

}  // namespace hemiroll::game
