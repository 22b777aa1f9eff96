#include "game/research/analysis/FeatureTable.h"

#include <cmath>
#include <cstdio>

#include "engine/record/CsvRowFormat.h"

namespace hemiroll::game {

namespace {

std::string number(double v) {
  std::string s;
  record::appendDouble(v, s);
  return s;
}

// Fixed decimals for people; "-" when there is nothing to show.
std::string shown(bool found, double v, int decimals) {
  if (!found || !std::isfinite(v)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

std::string notesOf(const AnalysedTrial& t) {
  std::string out;
  auto add = [&](const std::string& note) {
    if (note.empty()) return;
    out += (out.empty() ? "" : "; ") + note;
  };
  for (const std::string& n : t.data.notes) add(n);
  const analysis::TrialFeatures& f = t.features;
  if (!f.phases.found) add("phases: " + f.phases.reason);
  add(f.rose.found ? f.roseNote : f.rose.reason);
  if (!f.helix.arc.found) add(f.helix.arc.reason);
  if (!f.helix.loops.found) add(f.helix.loops.reason);
  return out;
}

}  // namespace

std::vector<std::string> featureColumns() {
  return {"duration_s", "steady_start_s", "steady_end_s", "steady_rate_rad_per_s",
          "steady_rate_spread_rad_per_s", "leaves", "leaves_per_cycle", "leaves_per_cycle_spread", "leaf_radius_m",
          "leaf_radius_spread_m", "outer_radius_m", "outer_radius_spread_m", "rose_start_s", "rose_end_s",
          "arc_curvature_per_m", "arc_curvature_error_per_m", "arc_rms_residual_m", "drift_speed_m_per_s", "loops",
          "loop_spacing_s", "loop_spacing_m", "loops_per_leaf", "guidance_work_J", "guidance_opposed_share", "notes"};
}

std::vector<std::string> featureCells(const AnalysedTrial& t) {
  const analysis::TrialFeatures& f = t.features;
  const auto& p = f.phases;
  const auto& r = f.rose;
  const auto& a = f.helix.arc;
  const auto& l = f.helix.loops;
  auto when = [](bool found, double v) { return found ? number(v) : std::string(); };
  return {number(p.trial.duration()), when(p.found, p.steady.start), when(p.found, p.steady.end),
          when(p.found, p.steadyRate), when(p.found, p.steadyRateSpread), r.found ? std::to_string(r.leaves) : "",
          when(r.found, r.leavesPerCycle), when(r.found, r.leavesPerCycleSpread), when(r.found, r.leafRadius.value),
          when(r.found, r.leafRadius.spread), when(r.found, r.outerRadius.value), when(r.found, r.outerRadius.spread),
          when(r.found, r.span.start), when(r.found, r.span.end), when(a.found, a.curvature),
          when(a.found, a.curvatureError), when(a.found, a.rmsResidual), number(a.driftSpeed),
          l.found ? std::to_string(l.count) : "", when(l.found, l.spacingTime.value), when(l.found, l.spacingArc.value),
          when(f.loopsPerLeaf > 0.0, f.loopsPerLeaf), when(t.guidance.present, t.guidance.work),
          when(t.guidance.present, t.guidance.opposedShare), notesOf(t)};
}

std::string featureTableCsv(const std::vector<AnalysedTrial>& trials) {
  std::vector<std::string> header = {"trial", "source"};
  for (std::string& c : featureColumns()) header.push_back(std::move(c));
  std::string out = record::csvLine(header);
  for (const AnalysedTrial& t : trials) {
    std::vector<std::string> row = {t.data.id, t.data.source};
    for (std::string& c : featureCells(t)) row.push_back(std::move(c));
    out += record::csvLine(row);
  }
  return out;
}

std::string featureTableMarkdown(const std::vector<AnalysedTrial>& trials) {
  std::string out =
      "| trial | duration [s] | steady phase [s] | rate [rad/s] | leaves | leaf radius [cm] | outer radius [cm] "
      "| rose span [s] | arc curvature [1/m] | loops | loop spacing [s] | guidance work [J] | opposed guidance [%] "
      "| notes |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const AnalysedTrial& t : trials) {
    const analysis::TrialFeatures& f = t.features;
    const auto& p = f.phases;
    const auto& r = f.rose;
    const auto& l = f.helix.loops;
    std::string notes = notesOf(t);
    for (char& c : notes)
      if (c == '|') c = '/';
    out += "| " + t.data.id + " | " + shown(true, p.trial.duration(), 1) + " | " +
           (p.found ? shown(true, p.steady.start, 1) + "-" + shown(true, p.steady.end, 1) : "-") + " | " +
           shown(p.found, p.steadyRate, 3) + " | " + (r.found ? std::to_string(r.leaves) : "-") + " | " +
           (r.found ? shown(true, 100.0 * r.leafRadius.value, 2) + " ± " + shown(true, 100.0 * r.leafRadius.spread, 2) : "-") +
           " | " +
           (r.found ? shown(true, 100.0 * r.outerRadius.value, 2) + " ± " + shown(true, 100.0 * r.outerRadius.spread, 2) : "-") +
           " | " + shown(r.found, r.span.duration(), 1) + " | " + shown(f.helix.arc.found, f.helix.arc.curvature, 1) +
           " | " + (l.found ? std::to_string(l.count) : "-") + " | " + shown(l.found, l.spacingTime.value, 2) + " | " +
           shown(t.guidance.present, t.guidance.work, 4) + " | " +
           shown(t.guidance.present, 100.0 * t.guidance.opposedShare, 1) + " | " + notes + " |\n";
  }
  return out;
}

}  // namespace hemiroll::game
