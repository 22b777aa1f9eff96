#pragma once
// What the results screen shows of a trial's end besides its numbers: the
// scene as the trial left it (the final pose and the contact trace, drawn
// behind the results), what decided the time, in the player's words, and the
// level's medal thresholds.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/render/ContactTrace.h"
#include "engine/render/RenderScene.h"
#include "engine/task/LevelDef.h"
#include "game/ui/screens/MedalTimes.h"
#include "game/trial/TrialJudge.h"

namespace hemiroll::game {

struct TrialEnding {
  render::RenderScene scene;                    // scene.trace points into `trace`
  std::unique_ptr<render::ContactTrace> trace;  // owned here, so the scene can move
  std::vector<std::string> decidedBy;           // explainEnding(), then explainLoop()
  task::ScoringDef scoring;
  std::optional<MedalTimes> medalTimes;         // the thresholds as times, where the score is a time
  bool hasScene = false;

  // The play screen's last frame: a copy of its scene and trace.
  static TrialEnding of(const render::RenderScene& scene, const render::ContactTrace* trace);
};

// What decided the trial's time, a line each: for a success the hold that
// completed it (from when, how long), for a failure the moment and the
// reason and what was still out of its band and what it needed, the furthest
// out first (the compact HUD's few rows, in the player's words: PlayerWords,
// screen directions for a camera whose screen right has this heading [rad]).
std::vector<std::string> explainEnding(const TrialResult& result, const task::TaskDef& task,
                                       double screenRightHeading = 0.0);

// What the servo loop's timing did to a trial in the window (issue 27: a
// summary that says so): its safety stops, and the stalls a device without
// force rode out (caught up, or the clock slowed).
struct LoopStory {
  bool forceOutput = false;         // the device renders force (stalls stop it)
  unsigned long long stalls = 0;    // wake-ups past the overrun limit
  double worstLateness = 0.0;       // [s]
  double slowedBy = 0.0;            // [s] of ticks not made up (the clock slowed)
  struct Stop {
    std::string what;
    double time = 0.0;              // [s] simulated
  };
  std::vector<Stop> stops;
};
std::vector<std::string> explainLoop(const LoopStory& story);

}  // namespace hemiroll::game
