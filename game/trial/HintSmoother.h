#pragma once
// The hint at a person's bandwidth (HintCoach for the human model,
// AutopilotCompanion for the window): the technique the tutorials teach
// (engine/human/Technique), worked out from the trial's state now and said
// as "trace this ring, this size, this pace" while it swirls or brakes, and
// "put the proxy over this spot and keep it still" while it settles. A new
// decision comes every `interval`, as a person's would; the ring's centre
// and the spot glide to it through a low-pass of `centreLag`.
//
// Drawn ahead: a person answers what the screen shows about half a second
// late (the visual delay, 0.2-0.25 s, and the next correction, an interval
// of 0.25 s later: docs/HUMAN_MODEL.md), so the ring and the spot are drawn
// where they will be by then: moved by `lead` times the velocity of c_up
// (where the hemisphere would stand upright), watched over `leadWatch`, and
// never further than `leadLimit`. Drawn for now, they came to the hand as
// late as the person's own reading and, with a second's low-pass on top,
// later (measured: the paper's task 13/20 at a delay of 0.25 s, against
// 17/20 without the hint).
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

struct HintSmootherDef {
  double interval = 0.25;   // between two decisions, a person's interval [s]
  double centreLag = 0.25;  // time constant of the glide of the ring's centre and the spot (an interval) [s]
  double lead = 0.5;        // drawn this far ahead: a person's visual delay and one interval [s]
  double leadWatch = 0.5;   // c_up's velocity is watched over this long [s]
  double leadLimit = 0.005; // the lead moves the ring or the spot at most this far [m]
};

class HintSmoother {
 public:
  explicit HintSmoother(const HintSmootherDef& def = {}) : def_(def) {}

  // After `autopilot.act(obs)`: the cue, `dt` [s] after the previous call.
  // None before the autopilot's first plan, on a stage without a contact
  // target (the technique there leans or turns on the spot: the HUD says
  // it) and after the autopilot gave up.
  human::HintCue cue(AutopilotBot& autopilot, const script::BotObservation& obs, double dt);
  // The same with the gate said: `planned` while the autopilot has a plan
  // (its first made, not given up). HintCoach's HintGate says it without
  // running the planner.
  human::HintCue cue(const script::BotObservation& obs, double dt, bool planned);
  // A new trial on a hemisphere of this radius [m].
  void reset(double radius);

 private:
  // Watches c_up's velocity (every call, shown or not).
  void watchUpright(const script::BotObservation& obs, double dt);

  HintSmootherDef def_;
  double radius_ = 0.04;
  std::optional<human::Technique> technique_;
  human::Movement movement_;
  double nextDecision_ = 0.0;
  bool started_ = false;
  physics::Vec2 centre_ = physics::Vec2::Zero();
  bool watching_ = false;
  physics::Vec2 upright_ = physics::Vec2::Zero();          // c_up at the last call [m]
  physics::Vec2 uprightVelocity_ = physics::Vec2::Zero();  // watched over leadWatch [m/s]
};

}  // namespace hemiroll::game
