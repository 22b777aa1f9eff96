#include "game/research/sweep/PointMeasurement.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/physics/StateLayout.h"
#include "game/research/sim/RoseLockstepRun.h"
#include "game/research/sim/ScenarioRun.h"

namespace hemiroll::game {

namespace {

// The analysis' reasons are one line already; a sweep row must never hold a
// line break (a partial CSV is cut at line ends on resume).
std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

}  // namespace

double PointMeasurement::steadyFraction() const {
  const analysis::Phases& p = features.phases;
  return p.found && duration > 0.0 ? p.steady.duration() / duration : 0.0;
}

double PointMeasurement::relativeSpread() const {
  const analysis::Phases& p = features.phases;
  return p.found && p.steadyRateMedian != 0.0 ? p.steadyRateSpread / std::abs(p.steadyRateMedian) : 0.0;
}

bool PointMeasurement::meetsPaper(const task::SweepAnalysisDef& def) const {
  return event == physics::DomainEvent::None && features.phases.found && steadyFraction() >= def.minSteadyFraction &&
         relativeSpread() <= def.maxRelativeSpread && helixInSteadyPhase && features.helix.arc.found &&
         features.helix.loops.found;
}

std::string PointMeasurement::notes() const {
  std::string out;
  auto add = [&](const std::string& what) { out += (out.empty() ? "" : "; ") + oneLine(what); };
  if (event != physics::DomainEvent::None) add(std::string("stopped by ") + physics::domainEventName(event));
  if (!features.phases.found) add("steady: " + features.phases.reason);
  if (!features.helix.arc.found) add("arc: " + features.helix.arc.reason);
  if (!features.helix.loops.found) add("loops: " + features.helix.loops.reason);
  if (!features.rose.found) add("rose: " + features.rose.reason);
  if (features.phases.found && !helixInSteadyPhase) add("helix: " + features.helixNote);
  return out;
}

double cosTiltLowerBound(double u, double v) {
  // cos x >= 1 - x^2/2 + x^4/24 - x^6/720 for every real x (integrate
  // 1 - cos x >= 0 six times from 0); where both bounds are >= 0, their
  // product bounds the product of the cosines.
  auto floorOfCos = [](double x) {
    const double x2 = x * x;
    return 1.0 - x2 * (1.0 / 2.0 - x2 * (1.0 / 24.0 - x2 * (1.0 / 720.0)));
  };
  const double fu = floorOfCos(u), fv = floorOfCos(v);
  return fu >= 0.0 && fv >= 0.0 ? fu * fv : -1.0;
}

long long sampleEvery(double timeStep) {
  return std::max(1LL, static_cast<long long>(std::llround(0.01 / timeStep)));
}

namespace {

RunSettings settingsOf(const task::SweepDef& def) {
  RunSettings settings;
  settings.duration = def.duration;
  settings.timeStep = def.timeStep;
  settings.integrator = def.integrator;
  settings.tolerance = def.tolerance;
  settings.every = sampleEvery(def.timeStep);
  return settings;
}

// The columns one point's rows fill, then the measurement made of them.
class PointRecorder {
 public:
  explicit PointRecorder(const RunSettings& settings) {
    const long long rows = ScenarioRun::stepCount(settings) / settings.every + 2;
    for (auto* column : {&time_, &massX_, &massY_, &contactX_, &contactY_, &psi_})
      column->reserve(static_cast<std::size_t>(rows));
  }

  void add(const TrajectoryRow& row) {
    namespace slot = physics::force_slot;
    time_.push_back(row.time);
    massX_.push_back(row.state[slot::x_p]);
    massY_.push_back(row.state[slot::y_p]);
    contactX_.push_back(row.state[slot::u_a]);
    contactY_.push_back(row.state[slot::v_a]);
    psi_.push_back(row.state[slot::psi]);
    // The face normal's vertical component is cos(u_o) cos(v_o): eq. (6)
    // with psi about the vertical (SweepTest checks it against Orientation).
    // Most rows are surely not a new maximum: where even the cosine's lower
    // bound lies 2e-9 above the least cosine seen, the cosine itself lies
    // more than 1e-9 above it (the bound errs by ~1e-15 in rounding), which
    // the test below would skip too; so two cos per row are saved without
    // changing what is kept.
    if (cosTiltLowerBound(row.state[slot::u_o], row.state[slot::v_o]) > leastCosTilt_ + 2e-9) return;
    const double cosTilt = std::cos(row.state[slot::u_o]) * std::cos(row.state[slot::v_o]);
    // acos only where the tilt may be a new maximum (issue 32: acos per row
    // was ~1 % of a sweep). acos falls with slope at least 1 in magnitude,
    // so a cosine more than 1e-9 above the least seen has an angle at least
    // 1e-9 below that one's, far beyond acos's rounding (an ulp, ~4e-16 at
    // pi): skipping it cannot change the maximum's bits.
    if (cosTilt <= leastCosTilt_ + 1e-9) {
      maxTilt_ = std::max(maxTilt_, std::acos(std::clamp(cosTilt, -1.0, 1.0)));
      leastCosTilt_ = std::min(leastCosTilt_, cosTilt);
    }
  }

  PointMeasurement finish(const task::SweepDef& def, const RunSummary& summary) const {
    PointMeasurement m;
    m.duration = def.duration;
    m.maxTilt = maxTilt_;
    m.event = summary.event;
    m.simulated = summary.endTime;
    if (m.event != physics::DomainEvent::None) m.eventTime = summary.endTime;
    if (m.simulated > 0.0) m.meanRate = (psi_.back() - psi_.front()) / m.simulated;
    analysis::TrialAnalysisDef judged;
    judged.phases.minRate = def.analysis.minRate;
    judged.phases.relativeBand = def.analysis.relativeBand;
    judged.phases.absoluteBand = def.analysis.absoluteBand;
    m.features = analysis::analyzeTrial({time_, massX_, massY_, contactX_, contactY_, psi_}, judged);
    m.helixInSteadyPhase = m.features.phases.found && m.features.helixNote.empty();
    m.paperLike = m.meetsPaper(def.analysis);
    return m;
  }

 private:
  std::vector<double> time_, massX_, massY_, contactX_, contactY_, psi_;
  double maxTilt_ = 0.0;
  double leastCosTilt_ = std::numeric_limits<double>::infinity();
};

PointMeasurement measureScenario(const task::SweepDef& def, const task::ScenarioDef& scenario,
                                 const RunSettings& settings) {
  PointRecorder recorder(settings);
  // StateOnly: the recorder reads the time, the position and the body's state alone.
  const RunSummary summary = ScenarioRun(scenario, settings, RowContent::StateOnly).run([&](const TrajectoryRow& row) {
    recorder.add(row);
  });
  return recorder.finish(def, summary);
}

}  // namespace

PointMeasurement measurePoint(const SweepGrid& grid, const SweepPoint& point) {
  return measureScenario(grid.def(), grid.scenario(point), settingsOf(grid.def()));
}

std::vector<PointMeasurement> measurePoints(const SweepGrid& grid, const std::vector<SweepPoint>& points,
                                            int laneWidth) {
  const RunSettings settings = settingsOf(grid.def());
  std::vector<task::ScenarioDef> scenarios;
  bool lockstep = laneWidth > 1 && points.size() > 1;
  for (const SweepPoint& point : points) {
    scenarios.push_back(grid.scenario(point));
    lockstep = lockstep && RoseLockstepRun::eligible(scenarios.back(), settings);
  }
  std::vector<PointMeasurement> out;
  if (!lockstep) {
    for (const task::ScenarioDef& scenario : scenarios) out.push_back(measureScenario(grid.def(), scenario, settings));
    return out;
  }
  std::vector<PointRecorder> recorders;  // each built in place: a copy would not keep the reserved columns
  recorders.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) recorders.emplace_back(settings);
  const std::vector<RunSummary> summaries = RoseLockstepRun(std::move(scenarios), settings, laneWidth,
                                                            RoseLockstepRun::RowContent::StateOnly)
                                                .run([&](std::size_t lane, const TrajectoryRow& row) {
                                                  recorders[lane].add(row);
                                                });
  for (std::size_t i = 0; i < points.size(); ++i) out.push_back(recorders[i].finish(grid.def(), summaries[i]));
  return out;
}

}  // namespace hemiroll::game
