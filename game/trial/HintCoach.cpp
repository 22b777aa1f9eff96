#include "game/trial/HintCoach.h"

#include "engine/autopilot/Autopilot.h"
#include "game/trial/AutopilotBot.h"

namespace hemiroll::game {

HintCoach::HintCoach(const HintCoachDef& def) : def_(def), smoother_(def.centreLag) {}
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
  smoother_.reset(info.params.radius);
}

std::string HintCoach::giveUpReason() const { return autopilot_ ? autopilot_->giveUpReason() : std::string(); }

human::HintCue HintCoach::hint(const script::BotObservation& obs) {
  if (!autopilot_ || !autopilot_->giveUpReason().empty()) return {};
  autopilot_->act(obs);
  return smoother_.cue(*autopilot_, obs, dt_);
}

}  // namespace hemiroll::game
