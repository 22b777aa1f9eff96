#include "game/trial/PassiveHandBot.h"

#include <algorithm>

namespace hemiroll::game {

void PassiveHandBot::init(const script::BotLevelInfo& info, std::int64_t) {
  dt_ = info.dt;
  holding_ = false;
  velocity_ = {};
}

script::BotAction PassiveHandBot::act(const script::BotObservation& obs) {
  if (!holding_) {  // takes hold where the mass point is, at rest
    holding_ = true;
    position_ = obs.mass;
    rest_ = obs.mass;
    lastTime_ = obs.time;
  } else {
    // The observation's time steps by one tick; a paused loop gives 0.
    const double dt = std::clamp(obs.time - lastTime_, 0.0, 10.0 * dt_);
    lastTime_ = obs.time;
    for (std::size_t i = 0; i < 3; ++i) {
      const double arm = -def_.stiffness * (position_[i] - rest_[i]) - def_.damping * velocity_[i];
      velocity_[i] += dt * (obs.deviceForce[i] + arm) / def_.mass;
      position_[i] += dt * velocity_[i];
      rest_[i] += dt * (position_[i] - rest_[i]) / def_.settleTime;
    }
  }
  script::BotAction a;
  a.position = position_;
  a.velocity = velocity_;
  a.hasVelocity = true;
  return a;
}

}  // namespace hemiroll::game
