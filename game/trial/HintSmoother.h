#pragma once
// The hint at a person's bandwidth (HintCoach for the human model,
// AutopilotCompanion for the window): the technique the tutorials teach
// (engine/human/Technique), worked out from the trial's state now and said
// as "trace this ring, this size, this pace" while it swirls or brakes, and
// "put the proxy over this spot and keep it still" while it settles. The
// ring's centre and the spot move through a low-pass of `centreLag`; a new
// decision comes every `interval`, as a person's would.
//
// Not the autopilot's own law: its 3 mm circle round a centre that rides on
// the contact tick by tick is a different system when a person traces it
// 0.2 s late (docs/HUMAN_MODEL.md: with it as the hint, tutorial 05 and the
// paper's task were lost in every run). The autopilot still gates the hint:
// none before its first plan and none once it has given up.

#include <optional>

#include "engine/human/ScreenView.h"
#include "engine/human/Technique.h"
#include "engine/script/BotObservation.h"

namespace hemiroll::game {

class AutopilotBot;

class HintSmoother {
 public:
  explicit HintSmoother(double centreLag = 1.0, double interval = 0.25) : centreLag_(centreLag), interval_(interval) {}

  // After `autopilot.act(obs)`: the cue, `dt` [s] after the previous call.
  // None before the autopilot's first plan, on a stage without a contact
  // target (the technique there leans or turns on the spot: the HUD says
  // it) and after the autopilot gave up.
  human::HintCue cue(AutopilotBot& autopilot, const script::BotObservation& obs, double dt);
  // A new trial on a hemisphere of this radius [m].
  void reset(double radius);

 private:
  double centreLag_;
  double interval_;
  double radius_ = 0.04;
  std::optional<human::Technique> technique_;
  human::Movement movement_;
  double nextDecision_ = 0.0;
  bool started_ = false;
  physics::Vec2 centre_ = physics::Vec2::Zero();
};

}  // namespace hemiroll::game
