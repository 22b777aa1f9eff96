#include "game/research/sweep/SweepMetrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/analysis/Statistics.h"

namespace hemiroll::game {

namespace {

constexpr const char* kAggregates[] = {"median", "mean", "min", "max", "best"};

}  // namespace

const char* aggregateName(Aggregate a) { return kAggregates[static_cast<int>(a)]; }

std::optional<Aggregate> parseAggregate(std::string_view name) {
  for (int i = 0; i < 5; ++i)
    if (name == kAggregates[i]) return static_cast<Aggregate>(i);
  return std::nullopt;
}

const std::vector<SweepMetric>& sweepMetrics() {
  using report::ColourMap;
  static const std::vector<SweepMetric> kMetrics = {
      {"paper_like", "paper-like", "share of points [-]", 1.0, ColourMap::Viridis,
       Aggregate::Mean, +1, false, true},
      {"steady_fraction", "steady share of the run", "share [-]", 1.0, ColourMap::Viridis,
       Aggregate::Median, +1, false, true},
      {"steady_rate_relative_spread", "relative spread of the rate", "relative spread [-]", 1.0,
       ColourMap::Viridis, Aggregate::Median, -1, false},
      {"steady_rate_rad_per_s", "steady precession rate", "rate [rad/s]", 1.0, ColourMap::Diverging,
       Aggregate::Median, 0, false},
      {"mean_rate_rad_per_s", "mean precession rate", "rate [rad/s]", 1.0, ColourMap::Diverging,
       Aggregate::Median, 0, false},
      {"arc_curvature_per_m", "arc curvature", "curvature [1/m]", 1.0, ColourMap::Diverging,
       Aggregate::Median, 0, false},
      {"arc_radius_m", "arc radius", "radius [cm]", 100.0, ColourMap::Viridis, Aggregate::Median, 0, false},
      {"arc_swept_angle_rad", "angle the arc sweeps", "angle [turns]", 0.5 / std::numbers::pi, ColourMap::Diverging,
       Aggregate::Median, 0, false},
      {"drift_speed_m_per_s", "drift speed", "speed [mm/s]", 1000.0, ColourMap::Viridis,
       Aggregate::Median, 0, false},
      {"loops", "loops", "loops [-]", 1.0, ColourMap::Viridis, Aggregate::Median, 0, false},
      {"loops_per_leaf", "loops per leaf", "loops per leaf [-]", 1.0, ColourMap::Viridis,
       Aggregate::Median, 0, false},
      {"max_tilt_rad", "largest tilt", "tilt [deg]", 180.0 / std::numbers::pi, ColourMap::Viridis, Aggregate::Median,
       -1, true},
      {"event_time_s", "time of the event", "time [s]", 1.0, ColourMap::Viridis, Aggregate::Median, +1, true},
      {"stopped", "stopped by an event", "share of points [-]", 1.0, ColourMap::Viridis, Aggregate::Mean,
       -1, true, true},
  };
  return kMetrics;
}

const SweepMetric* findSweepMetric(std::string_view name) {
  for (const SweepMetric& m : sweepMetrics())
    if (name == m.name) return &m;
  return nullptr;
}

std::string sweepMetricNames() {
  std::string out;
  for (const SweepMetric& m : sweepMetrics()) out += (out.empty() ? "" : ", ") + std::string(m.name);
  return out;
}

double aggregateValues(std::vector<double> values, Aggregate a, const SweepMetric& metric) {
  std::erase_if(values, [](double v) { return !std::isfinite(v); });
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  if (a == Aggregate::Best) a = metric.better > 0 ? Aggregate::Max : metric.better < 0 ? Aggregate::Min : Aggregate::Median;
  switch (a) {
    case Aggregate::Median: return analysis::median(values);
    case Aggregate::Mean: return analysis::mean(values);
    case Aggregate::Min: return *std::min_element(values.begin(), values.end());
    case Aggregate::Max:
    case Aggregate::Best: return *std::max_element(values.begin(), values.end());
  }
  return analysis::median(values);
}

}  // namespace hemiroll::game
