#include "game/ui/screens/TrialEnding.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "game/ui/hud/PlayHud.h"
#include "game/ui/hud/PlayerWords.h"

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

std::vector<std::string> explainEnding(const TrialResult& result, const task::TaskDef& task, double heading) {
  std::vector<std::string> lines;
  char line[200];
  const task::TrialSummary& s = result.summary;
  if (result.outcome == task::TrialOutcome::Success) {
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
  std::array<AdviceRow, 8> rows{};
  const int n = adviceRows(s.finalComponents, heading, rows);
  std::vector<const AdviceRow*> out;
  for (int i = 0; i < n; ++i)
    if (!rows[static_cast<std::size_t>(i)].inside) out.push_back(&rows[static_cast<std::size_t>(i)]);
  std::stable_sort(out.begin(), out.end(), [](const AdviceRow* a, const AdviceRow* b) { return a->margin < b->margin; });
  if (!out.empty()) lines.emplace_back("still out of its band at the end:");
  for (std::size_t i = 0; i < out.size() && i < static_cast<std::size_t>(PlayHud::kCompactRows); ++i)
    lines.push_back(std::string("  ") + out[i]->text.data());
  if (out.size() > static_cast<std::size_t>(PlayHud::kCompactRows)) {
    std::snprintf(line, sizeof line, "  and %zu more", out.size() - static_cast<std::size_t>(PlayHud::kCompactRows));
    lines.emplace_back(line);
  }
  return lines;
}

std::vector<std::string> explainLoop(const LoopStory& story) {
  std::vector<std::string> lines;
  char line[240];
  constexpr std::size_t kListed = 3;
  for (std::size_t i = 0; i < story.stops.size() && i < kListed; ++i) {
    std::snprintf(line, sizeof line, "safety stop at %.2f s: %s", story.stops[i].time, story.stops[i].what.c_str());
    lines.emplace_back(line);
  }
  if (story.stops.size() > kListed) {
    std::snprintf(line, sizeof line, "and %zu more safety stops", story.stops.size() - kListed);
    lines.emplace_back(line);
  }
  if (!story.forceOutput && story.stalls > 0) {
    if (story.slowedBy > 0.0)
      std::snprintf(line, sizeof line,
                    "the servo loop ran late %llu times (worst %.0f ms): a mouse renders no force, so play went on; "
                    "the clock slowed by %.0f ms in all",
                    story.stalls, story.worstLateness * 1e3, story.slowedBy * 1e3);
    else
      std::snprintf(line, sizeof line,
                    "the servo loop ran late %llu times (worst %.0f ms): a mouse renders no force, so play went on "
                    "and the loop caught up",
                    story.stalls, story.worstLateness * 1e3);
    lines.emplace_back(line);
  }
  return lines;
}

}  // namespace hemiroll::game
