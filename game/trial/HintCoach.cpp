#include "game/trial/HintCoach.h"


#include "engine/autopilot/Autopilot.h"
#include "game/trial/AutopilotBot.h"

namespace hemiroll::game {

HintCoach::HintCoach(const HintCoachDef& def) : def_(def) {}
HintCoach::~HintCoach() = default;

void HintCoach::init(const script::BotLevelInfo& info, std::int64_t seed) {
  AutopilotBotOptions options;
  // Half the planning effort: the hint is a coarse cue a person follows
  // late, and 0.5 still wins every shipped level (0.25 loses tutorial 02).
  options.budget = 0.5;
  options.holdsProxy = false;  // the person holds the proxy; the plan is a hint
  autopilot_ = std::make_unique<AutopilotBot>(options);
  autopilot_->init(info, seed);
  dt_ = info.dt;
  started_ = false;
}

std::string HintCoach::giveUpReason() const { return autopilot_ ? autopilot_->giveUpReason() : std::string(); }

human::HintCue HintCoach::hint(const script::BotObservation& obs) {
  human::HintCue cue;
  if (!autopilot_ || !autopilot_->giveUpReason().empty()) return cue;
  autopilot_->act(obs);
  // The autopilot's technique is a reaching one: a stage without a contact
  // target (a lean to hold, upright and still) gets no hint.
  if (!obs.targetSet[7] && !obs.targetSet[8]) return cue;
  if (!autopilot_->giveUpReason().empty() || autopilot_->autopilot() == nullptr) return cue;
  // Nothing to show before the autopilot has made its first plan: its law
  // starts circling by default, and a person who began to stir on that
  // would stir up a state its first plan then has to undo.
  if (autopilot_->autopilot()->stats().decisions == 0) return cue;
  const autopilot::HelixMotion& m = autopilot_->autopilot()->policy().motion();
  // Where the hint says to be moves slowly: the ring's centre, or the spot
  // to settle over, low-passed over a second (the autopilot's own settling
  // creeps at 1 kHz, which a person sees 0.2 s late and overshoots).
  const bool settling = m.phase == autopilot::HelixPhase::Settle;
  const physics::Vec2 wanted = settling ? m.goal : m.centre;
  if (!started_ || settling != settling_) {
    centre_ = wanted;
    started_ = true;
    settling_ = settling;
  }
  centre_ += (dt_ / def_.centreLag) * (wanted - centre_);
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
