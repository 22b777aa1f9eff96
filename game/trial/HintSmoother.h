#pragma once
// The autopilot's law turned into a hint at a person's bandwidth (HintCoach
// for the human model, AutopilotCompanion for the window): "trace this ring,
// this size, this pace" while it stirs, "put the proxy over this spot and
// keep it still" while it settles. The ring's centre and the spot move
// through a low-pass of `centreLag` (the autopilot's own centre rides on the
// contact tick by tick, which a person sees 0.2 s late and overshoots);
// size and pace change only when the autopilot changes what it does.

#include "engine/human/ScreenView.h"
#include "engine/script/BotObservation.h"

namespace hemiroll::game {

class AutopilotBot;

class HintSmoother {
 public:
  explicit HintSmoother(double centreLag = 1.0) : centreLag_(centreLag) {}

  // After `autopilot.act(obs)`: the cue, `dt` [s] after the previous call.
  // None before the autopilot's first plan (its law starts circling by
  // default, and a person who began to stir on that would stir up a state
  // its first plan must undo), on a stage without a contact target (the
  // technique is a reaching one) and after it gave up.
  human::HintCue cue(AutopilotBot& autopilot, const script::BotObservation& obs, double dt);
  void reset() { started_ = false; }

 private:
  double centreLag_;
  bool started_ = false;
  bool settling_ = false;
  physics::Vec2 centre_ = physics::Vec2::Zero();
};

}  // namespace hemiroll::game
