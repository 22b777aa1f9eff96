#include "game/research/sweep/SweepTable.h"

#include "engine/files/FileKinds.h"

#include <cmath>

#include <algorithm>
#include <stdexcept>

#include "engine/record/CsvRowFormat.h"
#include "engine/record/RecordError.h"
#include "engine/record/ResultsFile.h"
#include "game/research/sweep/SweepError.h"

namespace hemiroll::game {

namespace {

// Builds one row's fields in column order.
class Fields {
 public:
  Fields& number(double v) {
    std::string text;
    record::appendDouble(v, text);
    fields_.push_back(text);
    return *this;
  }
  // The value when `present`, else an empty cell.
  Fields& numberIf(bool present, double v) { return present ? number(v) : empty(); }
  Fields& integer(long long v) {
    fields_.push_back(std::to_string(v));
    return *this;
  }
  Fields& flag(bool v) { return integer(v ? 1 : 0); }
  Fields& text(std::string v) {
    fields_.push_back(std::move(v));
    return *this;
  }
  Fields& empty() { return text(""); }
  const std::vector<std::string>& all() const { return fields_; }

 private:
  std::vector<std::string> fields_;
};

}  // namespace

const std::vector<std::string>& sweepColumns() {
  static const std::vector<std::string> kColumns = [] {
    std::vector<std::string> c = {"point"};
    for (const task::SweepParamInfo& info : task::sweepParams()) c.emplace_back(info.column);
    for (const char* name :
         {"start_tilt_rad", "event", "event_time_s", "simulated_s", "max_tilt_rad", "mean_rate_rad_per_s",
          "steady_found", "steady_start_s", "steady_end_s", "steady_fraction", "steady_rate_rad_per_s",
          "steady_rate_spread_rad_per_s", "steady_rate_relative_spread", "helix_window", "arc_found",
          "arc_curvature_per_m", "arc_curvature_error_per_m", "arc_radius_m", "arc_rms_residual_m",
          "arc_swept_angle_rad", "drift_speed_m_per_s", "loops_found", "loops", "loop_spacing_s",
          "loop_spacing_spread_s", "loops_per_leaf", "rose_found", "leaves", "leaf_period_s", "paper_like", "notes"})
      c.emplace_back(name);
    return c;
  }();
  return kColumns;
}

std::string sweepHeader() { return record::csvLine(sweepColumns()); }

std::string sweepRow(const SweepPoint& point, const PointMeasurement& m) {
  const analysis::TrialFeatures& f = m.features;
  const analysis::Phases& p = f.phases;
  const analysis::ArcFeatures& arc = f.helix.arc;
  const analysis::LoopFeatures& loops = f.helix.loops;
  const analysis::RoseFeatures& rose = f.rose;
  const bool stopped = m.event != physics::DomainEvent::None;
  Fields row;
  row.integer(point.index);
  for (const task::SweepParamInfo& info : task::sweepParams())
    row.number(task::sweepParamValue(info.param, point.params, point.rose));
  row.number(point.startTilt)
      .text(stopped ? physics::domainEventName(m.event) : "none")
      .numberIf(stopped, m.eventTime)
      .number(m.simulated)
      .number(m.maxTilt)
      .number(m.meanRate)
      .flag(p.found)
      .numberIf(p.found, p.steady.start)
      .numberIf(p.found, p.steady.end)
      .number(m.steadyFraction())
      .numberIf(p.found, p.steadyRate)
      .numberIf(p.found, p.steadyRateSpread)
      .numberIf(p.found, m.relativeSpread())
      .text(m.helixInSteadyPhase ? "steady" : "whole")
      .flag(arc.found)
      .numberIf(arc.found, arc.curvature)
      .numberIf(arc.found, arc.curvatureError)
      .numberIf(arc.found, arc.radius)
      .numberIf(arc.found, arc.rmsResidual)
      .numberIf(arc.found, arc.sweptAngle)
      .numberIf(arc.span.duration() > 0.0, arc.driftSpeed)
      .flag(loops.found)
      .numberIf(loops.found, loops.count)
      .numberIf(loops.found, loops.spacingTime.value)
      .numberIf(loops.found, loops.spacingTime.spread)
      .numberIf(f.loopsPerLeaf > 0.0, f.loopsPerLeaf)
      .flag(rose.found)
      .numberIf(rose.found, rose.leaves)
      .numberIf(rose.found, rose.leafPeriod.value)
      .flag(m.paperLike)
      .text(m.notes());
  return record::csvLine(row.all());
}

std::size_t sweepColumn(std::string_view name) {
  const auto& c = sweepColumns();
  const auto at = std::find(c.begin(), c.end(), name);
  if (at == c.end()) throw std::out_of_range("no sweep column '" + std::string(name) + "'");
  return static_cast<std::size_t>(at - c.begin());
}

std::string sweepRowProblem(const std::vector<std::string>& fields) {
  const std::vector<std::string>& columns = sweepColumns();
  if (fields.size() != columns.size())
    return std::to_string(fields.size()) + " fields, a sweep row has " + std::to_string(columns.size());
  for (std::size_t i = 0; i < columns.size(); ++i) {
    const std::string& cell = fields[i];
    if (columns[i] == "notes" || columns[i] == "event") continue;
    if (columns[i] == "helix_window") {
      if (cell != "steady" && cell != "whole") return "column helix_window: '" + cell + "' is neither steady nor whole";
      continue;
    }
    if (cell.empty() && i > 0) continue;
    double value = 0.0;
    if (!record::parseDouble(cell, value) || !std::isfinite(value))
      return "column " + columns[i] + ": '" + cell.substr(0, 40) + "' is not a finite number (the CSV never holds NaN)";
  }
  return "";
}

std::vector<std::vector<std::string>> readSweepRows(const std::filesystem::path& csv) {
  std::error_code ec;
  if (!std::filesystem::exists(csv, ec)) throw SweepError(SweepError::Kind::BadInput, csv.string() + " is missing");
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> columns;
  try {
    record::ResultsFile(csv, files::kSweepTable).forEachRow(columns, [&](const std::vector<std::string>& fields, int line) {
      if (columns != sweepColumns())
        throw SweepError(SweepError::Kind::BadInput,
                         csv.string() + ": its columns are not this program's sweep columns (another version?)");
      if (const std::string problem = sweepRowProblem(fields); !problem.empty())
        throw SweepError(SweepError::Kind::BadInput, csv.string() + ": line " + std::to_string(line) + ": " + problem);
      rows.push_back(fields);
    });
  } catch (const record::RecordError& e) {
    throw SweepError(SweepError::Kind::BadInput, e.what());
  }
  if (columns != sweepColumns())
    throw SweepError(SweepError::Kind::BadInput,
                     csv.string() + ": its columns are not this program's sweep columns (another version?)");
  return rows;
}

}  // namespace hemiroll::game
