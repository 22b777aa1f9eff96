#pragma once
// The hint at a person's bandwidth for the human model (engine/human): the
// technique said as a ring to trace or a spot to settle over (HintSmoother:
// a movement a hand can follow late, never reversing within a second),
// shown while the autopilot would have a plan (HintGate). The window shows
// the same cue from its AutopilotCompanion.

#include <cstdint>
#include <string>

#include "engine/human/ScreenView.h"
#include "engine/script/BotObservation.h"
#include "game/trial/HintGate.h"
#include "game/trial/HintSmoother.h"

namespace hemiroll::game {

struct HintCoachDef {
  HintSmootherDef smoother;  // how the hint is drawn: the window's too
};

class HintCoach {
 public:
  explicit HintCoach(const HintCoachDef& def = {});

  void init(const script::BotLevelInfo& info, std::int64_t seed);
  // The hint for this tick.
  human::HintCue hint(const script::BotObservation& obs);
  // Non-empty once the autopilot has given up: no hint any more.
  std::string giveUpReason() const;

 private:
  HintCoachDef def_;
  HintGate gate_;
  HintSmoother smoother_;
  double dt_ = 0.001;
};

}  // namespace hemiroll::game
