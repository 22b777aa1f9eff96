#pragma once
// When the game shows the human model its hint (HintCoach): exactly when
// the autopilot would have a plan for the trial, said without running the
// planner. The autopilot plans from the first tick the coupling holds the
// mass point, and gives up for good once a stage asks for what it can tell
// at once it will never reach (autopilot/Reachability.h); that is the
// whole gate. Running the planner beside the person only to read that off
// cost about 40 s of CPU per 240 s trial of the paper's task against 0.1 s
// for the person (docs/HUMAN_MODEL.md).
//
// What this gate leaves out is the planner's own budget (AutopilotDef::
// planningRolloutSeconds): a planner that has worked too long on a trial
// gives up, but the hint is the technique (HintSmoother), not the
// planner's plan, and never costs that work.

#include <string>

#include "engine/autopilot/Reachability.h"
#include "engine/physics/HemisphereParams.h"
#include "engine/script/BotObservation.h"

namespace hemiroll::game {

class HintGate {
 public:
  // Throws script::ScriptError where the autopilot cannot plan the level at
  // all (a visual-only coupling), as AutopilotBot::init does.
  void init(const script::BotLevelInfo& info);
  // Whether the hint is shown for this observation.
  bool open(const script::BotObservation& obs);
  // Non-empty once a stage ruled the autopilot out: no hint any more.
  const std::string& reason() const { return reason_; }

 private:
  physics::HemisphereParams params_;
  autopilot::Workspace workspace_;
  bool planned_ = false;
  std::string reason_;
};

}  // namespace hemiroll::game
