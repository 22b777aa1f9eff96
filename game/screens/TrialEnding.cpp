#include "game/screens/TrialEnding.h"

#include <algorithm>
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
  // The furthest out first, as few as the compact HUD shows.
  std::vector<script::ComponentStatus> out;
  for (const script::ComponentStatus& c : s.finalComponents)
    if (!c.inside) out.push_back(c);
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    return a.normalizedMargin() < b.normalizedMargin();
  });
  if (!out.empty()) lines.emplace_back("furthest out of its band at the end:");
  for (std::size_t i = 0; i < out.size() && i < static_cast<std::size_t>(PlayHud::kCompactRows); ++i)
    lines.push_back("  " + PlayHud::componentLine(out[i]));
  if (out.size() > static_cast<std::size_t>(PlayHud::kCompactRows)) {
    std::snprintf(line, sizeof line, "  and %zu more", out.size() - static_cast<std::size_t>(PlayHud::kCompactRows));
    lines.emplace_back(line);
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
