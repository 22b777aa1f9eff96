#include "game/screens/TrialEnding.h"

#include <cstdio>

#include "game/hud/PlayHud.h"

namespace hemiroll::game {

TrialEnding TrialEnding::of(const render::RenderScene& scene, const render::ContactTrace* trace) {
  TrialEnding e;
  e.scene = scene;
  e.hasScene = true;
  if (trace) {
    e.trace = std::make_unique<render::ContactTrace>(*trace);
    e.scene.trace = e.trace.get();
  } else {
    e.scene.trace = nullptr;
  }
  return e;
}

std::vector<std::string> explainEnding(const TrialResult& result, const script::TaskDef& task) {
  std::vector<std::string> lines;
  char line[200];
  const script::TrialSummary& s = result.summary;
  if (result.outcome == script::TrialOutcome::Success) {
    const double hold = task.stages.empty() ? 0.0 : task.stages.back().hold;
    if (hold > 0.0)
      std::snprintf(line, sizeof line, "every band held for %.1f s, from %.2f s to %.2f s", hold, result.time - hold,
                    result.time);
    else
      std::snprintf(line, sizeof line, "inside every band at %.2f s", result.time);
    lines.emplace_back(line);
    if (s.stageCount > 1) {
      std::snprintf(line, sizeof line, "all %d stages passed", s.stageCount);
      lines.emplace_back(line);
    }
    return lines;
  }
  std::snprintf(line, sizeof line, "at %.2f s: %s", result.time, result.reason.c_str());
  lines.emplace_back(line);
  if (s.stageCount > 1) {
    std::snprintf(line, sizeof line, "%d of %d stages passed", s.stagesPassed, s.stageCount);
    lines.emplace_back(line);
  }
  bool heading = false;
  for (const script::ComponentStatus& c : s.finalComponents) {
    if (c.inside) continue;
    if (!heading) lines.emplace_back("out of its band at the end:");
    heading = true;
    lines.push_back("  " + PlayHud::componentLine(c));
  }
  return lines;
}

std::string medalThresholds(const script::ScoringDef& scoring) {
  if (!scoring.hasMedals) return "";
  char line[160];
  std::snprintf(line, sizeof line, "bronze %g, silver %g, gold %g points", scoring.bronze, scoring.silver,
                scoring.gold);
  return line;
}

}  // namespace hemiroll::game
