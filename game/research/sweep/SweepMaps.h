#pragma once
// Maps of a finished sweep (docs/SWEEP.md, "Maps"): a metric over two of its
// axes as a heatmap (game/research/report). When the sweep has more axes, each cell
// holds every point with those two values, aggregated as asked (the title
// says how, over which axes and how many points per cell). Runs stopped by a
// domain event count only for metrics where their value means something
// (the event's time, the largest tilt, "stopped"); a cell whose runs all
// stopped is grey and marked T (tipped over), F (left the face) or X (non-
// finite), a cell where only some did is marked t; a grey cell without a
// mark has no value because the feature was not found.

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/task/SweepDef.h"
#include "game/research/report/Heatmap.h"
#include "game/research/sweep/SweepManifest.h"
#include "game/research/sweep/SweepMetrics.h"

namespace hemiroll::game {

struct SweepData {
  SweepManifest manifest;
  task::SweepDef spec;
  std::vector<std::vector<std::string>> rows;  // point order, every point
};

// sweep.json (complete, the whole sweep) and sweep.csv from a folder that a
// sweep or a merge wrote. Throws SweepError naming what is wrong.
SweepData loadSweep(const std::filesystem::path& dir);

struct MapRequest {
  task::SweepParam x = task::SweepParam::k, y = task::SweepParam::Omega;
  const SweepMetric* metric = nullptr;
  std::optional<Aggregate> aggregate;  // unset: the metric's default
};

// Throws SweepError (bad input) when x or y is not an axis of the sweep, or
// they are the same. The title names the metric, and when a cell holds more
// than one point, the aggregate, the axes it runs over and the points per
// cell; `compact` keeps only the aggregate's name (a sheet's title says the rest).
report::HeatmapDef sweepHeatmap(const SweepData& data, const MapRequest& request, bool compact = false);

// The metrics drawn on each automatic sheet.
const std::vector<const char*>& sheetMetrics();
// One sheet per pair of axes ("map-<x>-<y>.svg", every sheetMetrics()
// panel); none for a sweep with one axis.
std::vector<std::pair<std::string, std::string>> sweepMapSheets(const SweepData& data);

}  // namespace hemiroll::game
