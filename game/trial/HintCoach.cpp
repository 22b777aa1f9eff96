#include "game/trial/HintCoach.h"

namespace hemiroll::game {

HintCoach::HintCoach(const HintCoachDef& def) : def_(def), smoother_(def.smoother) {}

void HintCoach::init(const script::BotLevelInfo& info, std::int64_t /*seed*/) {
  gate_.init(info);
  dt_ = info.dt;
  smoother_.reset(info.params.radius);
}

std::string HintCoach::giveUpReason() const { return gate_.reason(); }

human::HintCue HintCoach::hint(const script::BotObservation& obs) {
  const bool planned = gate_.open(obs);
  return smoother_.cue(obs, dt_, planned);
}

}  // namespace hemiroll::game
