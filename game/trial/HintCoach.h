#pragma once
// The hint at a person's bandwidth for the human model (engine/human): an
// autopilot of its own, planning at half effort beside the simulated
// person, its law said as a ring to trace or a spot to settle over
// (HintSmoother: a movement a hand can follow late, never reversing within
// a second). The window shows the same cue from its AutopilotCompanion.

#include <cstdint>
#include <memory>

#include "engine/human/ScreenView.h"
#include "engine/script/BotObservation.h"
#include "game/trial/HintSmoother.h"

namespace hemiroll::game {

class AutopilotBot;

struct HintCoachDef {
  double centreLag = 1.0;  // time constant of the low-pass on the ring's centre and the settle spot [s]
};

class HintCoach {
 public:
  explicit HintCoach(const HintCoachDef& def = {});
  ~HintCoach();

  void init(const script::BotLevelInfo& info, std::int64_t seed);
  // The hint for this tick (the autopilot answers the observation too).
  human::HintCue hint(const script::BotObservation& obs);
  // Non-empty once the autopilot has given up: no hint any more.
  std::string giveUpReason() const;

 private:
  HintCoachDef def_;
  std::unique_ptr<AutopilotBot> autopilot_;
  HintSmoother smoother_;
  double dt_ = 0.001;
};

}  // namespace hemiroll::game
