#include "game/research/sweep/SweepMaps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "engine/record/CsvRowFormat.h"
#include "game/research/report/LinePlot.h"
#include "game/research/report/PlotSheet.h"
#include "game/research/sweep/SweepError.h"
#include "game/research/sweep/SweepGrid.h"
#include "game/research/sweep/SweepSpecJson.h"
#include "game/research/sweep/SweepTable.h"

namespace hemiroll::game {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

[[noreturn]] void badInput(const std::string& message) { throw SweepError(SweepError::Kind::BadInput, message); }

// How an axis is drawn: centres in increasing order and the place of each
// of the axis' values among them.
struct AxisView {
  std::vector<double> centres;
  std::vector<std::size_t> placeOf;  // value index -> centre index
  report::AxisSpec spec;
};

AxisView viewOf(const task::SweepAxis& axis) {
  const task::SweepParamInfo& info = task::sweepParamInfo(axis.param);
  const bool length = axis.param == task::SweepParam::R || axis.param == task::SweepParam::r1 ||
                      axis.param == task::SweepParam::r2;
  std::vector<double> coordinate;
  for (double v : axis.values) coordinate.push_back(axis.log ? std::log10(std::abs(v)) : v);
  std::vector<std::size_t> order(coordinate.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return coordinate[a] < coordinate[b]; });
  AxisView view;
  view.placeOf.resize(order.size());
  for (std::size_t c = 0; c < order.size(); ++c) {
    view.centres.push_back(coordinate[order[c]]);
    view.placeOf[order[c]] = c;
  }
  const std::string name = info.name;
  if (axis.log) {
    view.spec.label = "log10 " + std::string(info.label);
  } else if (length) {
    view.spec.label = name + " [cm]";
    view.spec.scale = 100.0;
  } else {
    view.spec.label = info.label;
  }
  return view;
}

std::size_t axisIndex(const task::SweepDef& spec, task::SweepParam param) {
  for (std::size_t a = 0; a < spec.axes.size(); ++a)
    if (spec.axes[a].param == param) return a;
  std::string axes;
  for (const task::SweepAxis& a : spec.axes) axes += (axes.empty() ? "" : ", ") + std::string(task::sweepParamInfo(a.param).name);
  badInput(std::string(task::sweepParamInfo(param).name) + " is not an axis of this sweep (its axes: " + axes + ")");
}

char eventMark(const std::string& event) {
  if (event == "tipped_over") return 'T';
  if (event == "left_face") return 'F';
  return 'X';
}

// One cell's points -> value and mark.
struct Cell {
  std::vector<double> values;
  int points = 0, stopped = 0;
  char allStoppedBy = 0;
};

double metricValue(const std::vector<std::string>& row, const SweepMetric& metric, bool stopped) {
  if (std::string_view(metric.name) == "stopped") return stopped ? 1.0 : 0.0;
  double v = kNaN;
  const std::string& text = row[sweepColumn(metric.name)];
  if (!text.empty() && !record::parseDouble(text, v)) v = kNaN;
  return v;
}

std::string otherAxes(const task::SweepDef& spec, std::size_t ax, std::size_t ay) {
  std::string out;
  for (std::size_t a = 0; a < spec.axes.size(); ++a)
    if (a != ax && a != ay) out += (out.empty() ? "" : ", ") + std::string(task::sweepParamInfo(spec.axes[a].param).name);
  return out;
}

}  // namespace

SweepData loadSweep(const fs::path& dir) {
  const fs::path manifestPath = dir / "sweep.json";
  std::error_code ec;
  if (!fs::is_regular_file(manifestPath, ec))
    badInput(dir.string() + " holds no finished sweep (no sweep.json; a shard's folder needs `hemiroll sweep merge` first)");
  SweepData data;
  data.manifest = readManifest(manifestPath);
  if (!data.manifest.complete || !data.manifest.shard.whole())
    badInput(manifestPath.string() + " is not a complete sweep (shard " + data.manifest.shard.label() +
             (data.manifest.complete ? "" : ", incomplete") + ")");
  data.spec = specFromJson(data.manifest.specJson, manifestPath.string());
  data.rows = readSweepRows(dir / data.manifest.csv);
  if (static_cast<long long>(data.rows.size()) != data.spec.pointCount())
    badInput((dir / data.manifest.csv).string() + " holds " + std::to_string(data.rows.size()) + " rows; the spec has " +
             std::to_string(data.spec.pointCount()) + " points");
  return data;
}

report::HeatmapDef sweepHeatmap(const SweepData& data, const MapRequest& request, bool compact) {
  const task::SweepDef& spec = data.spec;
  const SweepMetric& metric = *request.metric;
  const std::size_t ax = axisIndex(spec, request.x), ay = axisIndex(spec, request.y);
  if (ax == ay) badInput("--x and --y name the same axis; a map needs two");
  const AxisView xv = viewOf(spec.axes[ax]), yv = viewOf(spec.axes[ay]);
  const std::size_t nx = xv.centres.size(), ny = yv.centres.size();
  const Aggregate aggregate = request.aggregate.value_or(metric.aggregate);

  const SweepGrid grid(spec);
  const std::size_t event = sweepColumn("event");
  std::vector<Cell> cells(nx * ny);
  for (long long i = 0; i < grid.size(); ++i) {
    const SweepPoint p = grid.point(i);
    const std::vector<std::string>& row = data.rows[static_cast<std::size_t>(i)];
    Cell& cell = cells[yv.placeOf[static_cast<std::size_t>(p.position[ay])] * nx +
                       xv.placeOf[static_cast<std::size_t>(p.position[ax])]];
    const bool stopped = row[event] != "none";
    ++cell.points;
    if (stopped) {
      cell.allStoppedBy = cell.stopped == 0 || cell.allStoppedBy == eventMark(row[event]) ? eventMark(row[event]) : 'X';
      ++cell.stopped;
    }
    if (!stopped || metric.includeStopped) cell.values.push_back(metricValue(row, metric, stopped));
  }

  report::HeatmapDef map;
  map.x = xv.spec;
  map.y = yv.spec;
  map.xCentres = xv.centres;
  map.yCentres = yv.centres;
  map.colourBarLabel = metric.unit;
  map.valueScale = metric.scale;
  map.map = metric.map;
  std::string shown;  // the marks that appear, for the note
  for (const Cell& c : cells) {
    map.values.push_back(aggregateValues(c.values, aggregate, metric));
    const bool all = c.stopped == c.points && c.points > 0;
    map.marks.push_back(all ? std::string(1, c.allStoppedBy) : c.stopped > 0 ? "t" : "");
    if (!map.marks.back().empty() && shown.find(map.marks.back()) == std::string::npos) shown += map.marks.back();
  }
  if (metric.share) map.min = 0.0, map.max = 1.0;
  if (metric.map == report::ColourMap::Diverging) {  // centred on 0
    double largest = 0.0;
    for (double v : map.values)
      if (std::isfinite(v)) largest = std::max(largest, std::abs(v));
    if (largest > 0.0) map.min = -largest, map.max = largest;
  }
  const std::size_t perCell = static_cast<std::size_t>(grid.size()) / (nx * ny);
  map.title = metric.title;
  if (perCell > 1 && compact) map.title += std::string(" (") + aggregateName(aggregate) + ")";
  if (perCell > 1 && !compact)
    map.title += std::string(", ") + aggregateName(aggregate) + " over " + otherAxes(spec, ax, ay) + " (" +
                 std::to_string(perCell) + " points/cell)";
  map.missingNote = "no value";
  for (const auto& [mark, meaning] : {std::pair{'T', "tipped over"}, std::pair{'F', "left the face"},
                                      std::pair{'X', "stopped (non-finite or mixed)"}, std::pair{'t', "some stopped"}})
    if (shown.find(mark) != std::string::npos) map.missingNote += std::string("; ") + mark + ": " + meaning;
  map.annotate = nx * ny <= 64;
  return map;
}

const std::vector<const char*>& sheetMetrics() {
  static const std::vector<const char*> kSheet = {
      "paper_like", "steady_fraction", "steady_rate_relative_spread", "steady_rate_rad_per_s", "arc_curvature_per_m",
      "drift_speed_m_per_s", "loops_per_leaf", "max_tilt_rad", "stopped"};
  return kSheet;
}

std::vector<std::pair<std::string, std::string>> sweepMapSheets(const SweepData& data) {
  std::vector<std::pair<std::string, std::string>> sheets;
  const auto& axes = data.spec.axes;
  for (std::size_t a = 0; a < axes.size(); ++a) {
    for (std::size_t b = a + 1; b < axes.size(); ++b) {
      const char* x = task::sweepParamInfo(axes[a].param).name;
      const char* y = task::sweepParamInfo(axes[b].param).name;
      const long long perCell = static_cast<long long>(data.rows.size() / (axes[a].values.size() * axes[b].values.size()));
      std::string title = fs::path(data.manifest.specFile).filename().string() + ": " + x + " x " + y + ", " +
                          std::to_string(data.rows.size()) + " points from " +
                          (data.spec.start == task::SweepStart::Rest ? "rest" : "the static tilt");
      if (perCell > 1) title += "; each cell aggregates " + std::to_string(perCell) + " over " + otherAxes(data.spec, a, b);
      report::PlotSheet sheet(3, 480.0, 360.0, title + " (" + data.manifest.specHash + ")");
      for (const char* name : sheetMetrics())
        sheet.add(sweepHeatmap(data, {axes[a].param, axes[b].param, findSweepMetric(name), std::nullopt}, true));
      sheets.emplace_back(std::string("map-") + x + "-" + y + ".svg", sheet.svg());
    }
  }
  return sheets;
}

}  // namespace hemiroll::game
