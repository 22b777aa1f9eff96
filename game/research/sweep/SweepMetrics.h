#pragma once
// The metrics a sweep map can show (docs/SWEEP.md, "Maps"): a CSV column
// (or "stopped", derived from `event`), how to show it, and how the points
// of one cell are aggregated when the sweep has more axes than the map.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "game/research/report/ColourMap.h"

namespace hemiroll::game {

enum class Aggregate { Median, Mean, Min, Max, Best };

const char* aggregateName(Aggregate a);
std::optional<Aggregate> parseAggregate(std::string_view name);

struct SweepMetric {
  const char* name;              // the CSV column, or "stopped"
  const char* title;             // what it is, short: the plot title (a sheet's panels are narrow)
  const char* unit;              // colour bar label, with the displayed unit
  double scale = 1.0;            // displayed = value * scale
  report::ColourMap map = report::ColourMap::Viridis;  // Diverging: signed, centred on 0
  Aggregate aggregate = Aggregate::Median;  // the default over the other axes
  int better = 0;                // +1 larger is better, -1 smaller; 0: Best means the median
  bool includeStopped = false;   // a run stopped by an event (tip-over) has a meaningful value
  bool share = false;            // a share in [0, 1]: the colour bar always spans [0, 1]
};

const std::vector<SweepMetric>& sweepMetrics();
const SweepMetric* findSweepMetric(std::string_view name);
// "a, b, c" for messages.
std::string sweepMetricNames();

// The aggregate of finite values (NaN for none); Best takes the metric's
// better end (the median when it has none).
double aggregateValues(std::vector<double> values, Aggregate a, const SweepMetric& metric);

}  // namespace hemiroll::game
