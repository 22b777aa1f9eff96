#pragma once
// What the results screen shows of a trial's end besides its numbers: the
// scene as the trial left it (the final pose and the contact trace, drawn
// behind the results), what decided the time, in the player's words, and the
// level's medal thresholds.

#include <memory>
#include <string>
#include <vector>

#include "engine/render/ContactTrace.h"
#include "engine/render/RenderScene.h"
#include "engine/script/LevelDef.h"
#include "game/trial/TrialJudge.h"

namespace hemiroll::game {

struct TrialEnding {
  render::RenderScene scene;                    // scene.trace points into `trace`
  std::unique_ptr<render::ContactTrace> trace;  // owned here, so the scene can move
  std::vector<std::string> decidedBy;           // explainEnding()
  script::ScoringDef scoring;
  bool hasScene = false;

  // The play screen's last frame: a copy of its scene and trace.
  static TrialEnding of(const render::RenderScene& scene, const render::ContactTrace* trace);
};

// What decided the trial's time, a line each: for a success the hold that
// completed it (from when, how long), for a failure the moment and the
// reason and what was still out of its band and by how much, the furthest
// out first (player units, PlayHud::componentLine; the compact HUD's few).
std::vector<std::string> explainEnding(const TrialResult& result, const script::TaskDef& task);

// "bronze 500, silver 800, gold 900 points", "" without medals.
std::string medalThresholds(const script::ScoringDef& scoring);

}  // namespace hemiroll::game
