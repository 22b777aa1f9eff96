#pragma once
// Turns the servo loop's state after a tick into what a bot sees
// (script::BotObservation) and what a level's callbacks see
// (script::TrialObservation): mass point, face axes, contact point in the
// scene frame, and the current stage's targets from the judge. Pure
// computation on plain numbers; allocates nothing, so it may run every tick.

#include "engine/haptics/ServoSnapshot.h"
#include "engine/haptics/WorkspaceMapping.h"
#include "engine/physics/HemisphereParams.h"
#include "engine/physics/StateLayout.h"
#include "engine/script/BotObservation.h"
#include "engine/task/TaskJudge.h"

namespace hemiroll::game {

class ObservationBuilder {
 public:
  // `mapping`: the device's, to turn the rendered force back into the scene.
  ObservationBuilder(const physics::HemisphereParams& params, const haptics::WorkspaceMapping& mapping)
      : constants_(params), mapping_(mapping) {}

  // `time`, `state`: the loop's after the last tick; `snapshot`: its last
  // published tick (proxy, force, engagement), or a default one before the
  // first tick; `judge`: the task as it stands.
  void fill(double time, const physics::ForceDrivenState& state, const haptics::ServoSnapshot& snapshot,
            const task::TaskJudge& judge, script::BotObservation& out) const;
  // The two halves of fill, for a planner on another thread than the judge:
  // the state's part (any thread) and the task's part (the judge's thread).
  void fillKinematics(double time, const physics::ForceDrivenState& state, const haptics::ServoSnapshot& snapshot,
                      script::BotObservation& out) const;
  static void fillTask(const task::TaskJudge& judge, script::BotObservation& out);

 private:
  physics::ModelConstants constants_;
  haptics::WorkspaceMapping mapping_;
};

}  // namespace hemiroll::game
