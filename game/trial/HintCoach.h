#pragma once
// The hint at a person's bandwidth: what the autopilot is doing, said as a
// movement a hand can follow late (visual delay 0.2 s, a correction every
// 0.25 s or more): "trace this ring, this size, this pace", or "put the
// proxy over this spot and keep it still". The autopilot's own proxy goes
// round a centre that rides on the contact tick by tick; the ring's centre
// here moves slowly (a low-pass of a second) and its size and pace only
// change when the autopilot changes what it does, so a hint never reverses
// within a second. The window draws it (a ring on the floor, a settle
// marker); the human model follows it (engine/human).

#include <cstdint>
#include <memory>

#include "engine/human/ScreenView.h"
#include "engine/script/BotObservation.h"

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
  double dt_ = 0.001;
  bool started_ = false;
  bool settling_ = false;
  physics::Vec2 centre_ = physics::Vec2::Zero();
};

}  // namespace hemiroll::game
