#pragma once
// The built-in bot "passive-hand": a hand that holds the device without
// intent, as a participant told "let the device lead you" does. It takes
// hold of the mass point at rest and then only yields to what the device
// pushes it with (BotObservation::deviceForce), through a relaxed arm:
//
//   m a = F_device - k (x - a) - b v,     da/dt = (x - a) / tau
//
// The arm's spring pulls towards where the hand has been lately (a), not
// towards any goal: it steadies the hand against quick pushes (a limp hand
// lets the hemisphere topple while the force ramps in) and gives way to a
// push that lasts. Semi-implicit Euler at the trial's tick. Alone it does
// not solve anything; with haptic guidance it shows what the guidance does
// by itself, so a guidance protocol runs end to end headless.

#include <string>

#include "engine/script/BotPolicy.h"

namespace hemiroll::game {

inline constexpr const char* kPassiveHandBotName = "passive-hand";

struct PassiveHandDef {
  double mass = 0.3;        // hand and device mass [kg] (HandModelDef's)
  double stiffness = 150.0; // k, the relaxed arm [N/m] (half HandModelDef's grip)
  double damping = 10.0;    // b [N s/m]
  double settleTime = 1.0;  // tau: how fast the arm's rest follows the hand [s]
};

class PassiveHandBot final : public script::BotPolicy {
 public:
  explicit PassiveHandBot(const PassiveHandDef& def = {}) : def_(def) {}

  const std::string& name() const override { return name_; }
  void init(const script::BotLevelInfo& info, std::int64_t seed) override;
  script::BotAction act(const script::BotObservation& obs) override;

 private:
  PassiveHandDef def_;
  std::string name_ = kPassiveHandBotName;
  double dt_ = 0.001;
  bool holding_ = false;
  double lastTime_ = 0.0;
  script::Triple3 position_{}, velocity_{}, rest_{};
};

}  // namespace hemiroll::game
