#include "game/trial/HintGate.h"

#include "engine/physics/StateKinematics.h"
#include "engine/script/ScriptError.h"
#include "game/trial/AutopilotBot.h"

namespace hemiroll::game {

void HintGate::init(const script::BotLevelInfo& info) {
  if (info.coupling.visualOnly)
    throw script::ScriptError("autopilot: a visual-only coupling hides the method that drives the model");
  params_ = info.params;
  workspace_.centre = physics::vec3Of(info.workspaceCentre);
  workspace_.radius = info.workspaceRadius;
  planned_ = false;
  reason_.clear();
}

bool HintGate::open(const script::BotObservation& obs) {
  if (!reason_.empty()) return false;
  // What Autopilot::takeGoal refuses a stage for (its psi band plays no
  // part in reachability).
  reason_ = autopilot::unreachableReason(goalOf(obs), params_, workspace_);
  if (!reason_.empty()) {
    reason_ = "autopilot: " + reason_;
    return false;
  }
  planned_ = planned_ || obs.engaged;
  return planned_;
}

}  // namespace hemiroll::game
