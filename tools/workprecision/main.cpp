// work_precision: run time against error for our integrators and the peers
// (issue 3), plus the long-horizon invariant of the undamped tether.
//
//   work_precision [--quick] [--only SCENARIO] [--out DIR] [--doc FILE.md]
//
// Writes DIR/work_precision.csv, DIR/energy_drift.csv, DIR/work_precision.gp
// (gnuplot script for DIR/work_precision.png) and the markdown summary.
// Exit 1 if a reference check fails (two tight references disagree by more
// than 1e-9: a horizon outside the predictability window) or an output
// cannot be written.

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "engine/physics/DormandPrince54.h"
#include "engine/physics/DormandPrince853.h"
#include "engine/physics/Tsitouras54.h"
#include "engine/physics/Verner76.h"
#include "engine/physics/Verner98.h"
#include "engine/physics/GaussLegendre.h"
#include "tools/workprecision/PeerSolvers.h"
#include "tools/workprecision/WorkPrecisionReport.h"
#include "tools/workprecision/WorkPrecisionScenarios.h"

namespace hemiroll::tools {
namespace {

using namespace physics;

double cpuNow() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Settings {
  bool quick = false;
  double targetSeconds = 0.15;  // repeat a run until about this much CPU time, median taken
  int minRepeats = 3, maxRepeats = 15;
  std::string only;  // --only NAME: that scenario alone, no invariant table (for development)
};

// Median CPU time of `run` (which returns its result), and that result.
template <class Run>
auto timed(const Settings& s, const Run& run, double& seconds) {
  double t0 = cpuNow();
  auto result = run();
  std::vector<double> times{cpuNow() - t0};
  const int repeats =
      s.quick ? 1 : std::clamp(static_cast<int>(s.targetSeconds / std::max(times[0], 1e-6)), s.minRepeats, s.maxRepeats);
  for (int i = 1; i < repeats; ++i) {
    t0 = cpuNow();
    result = run();
    times.push_back(cpuNow() - t0);
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  seconds = times[times.size() / 2];
  return result;
}

template <int N>
struct RunResult {
  StateVector<N> x;
  long long evaluations = 0;
};

template <int N, class Method>
RunResult<N> runFixed(const Scenario<N>& s, double h) {
  Method method;
  const long long steps = std::llround(s.horizon / h);
  StateVector<N> x = s.x0;
  for (long long i = 0; i < steps; ++i) method.step(*s.system, static_cast<double>(i) * h, x, h);
  long long evaluations = steps * 4;
  if constexpr (requires { method.evaluations(); }) evaluations = method.evaluations();
  return {x, evaluations};
}

template <int N, class Method>
RunResult<N> runAdaptive(const Scenario<N>& s, double tol) {
  Method method;
  method.setTolerance(tol);
  double t = 0.0;
  StateVector<N> x = s.x0;
  method.advanceTo(*s.system, t, x, s.horizon);
  return {x, method.statistics().evaluations};
}

template <int N>
double errorOf(const StateVector<N>& x, const StateVector<N>& ref) {
  return x.allFinite() ? (x - ref).cwiseAbs().maxCoeff() : std::numeric_limits<double>::infinity();
}

// The reference end state: our DOP853 in long double at tol 1e-16, checked
// against a second one at 1e-15. Returns it; `floor` is the error below
// which a point cannot be told from the reference's own.
template <int N>
StateVector<N> referenceOf(const Scenario<N>& s, std::vector<ReferenceCheck>& refs, double& floor) {
  double refSeconds = 0.0;
  const double t0 = cpuNow();
  // Tol 1e-16 is meaningful here: the state and the step updates are in long
  // double, only the right-hand side rounds to double (relative 1e-16 of a
  // stage derivative, times h, per step).
  const StateVector<N> ref = runAdaptive<N, DormandPrince853LongDouble<N>>(s, 1e-16).x;
  refSeconds = cpuNow() - t0;
  const StateVector<N> ref2 = runAdaptive<N, DormandPrince853LongDouble<N>>(s, 1e-15).x;
  const double disagreement = errorOf<N>(ref2, ref);
  refs.push_back({s.name, s.horizon, disagreement, refSeconds});
  // Errors must stand well clear of what the reference itself may be off by:
  // the disagreement bounds the error of the looser of the two references,
  // so 10x it is >= 10x the error of the reference used.
  floor = 10.0 * std::max(disagreement, 1e-16);
  return ref;
}

// Tolerances 1, 2, 5 per decade from 1e-3 to 1e-14, the same for every
// adaptive method, ours and the peers': at the end of a chaotic horizon the
// error is not monotone in tol, and a coarse grid makes the interpolated
// times depend on where the decade points happen to fall.
std::vector<double> tolerances(bool quick) {
  if (quick) return {1e-5, 1e-8};
  std::vector<double> tols;
  for (int e = -3; e >= -14; --e)
    for (double m : {5.0, 2.0, 1.0})
      if (e < -3 || m == 1.0) tols.push_back(m * std::pow(10.0, e));
  return tols;
}

// One adaptive method at one tol, timed over the passes.
template <int N>
struct AdaptiveJob {
  std::string method;
  bool ours;
  double tol;
  std::function<RunResult<N>()> run;
  RunResult<N> result;
  std::vector<double> seconds;
};

template <int N>
std::vector<AdaptiveJob<N>> adaptiveJobs(const Scenario<N>& s, const std::vector<double>& tols) {
  std::vector<AdaptiveJob<N>> jobs;
  for (double tol : tols) {
    jobs.push_back({"dopri5", true, tol, [&s, tol] { return runAdaptive<N, DormandPrince54<N>>(s, tol); }, {}, {}});
    jobs.push_back({"tsit5", true, tol, [&s, tol] { return runAdaptive<N, Tsitouras54<N>>(s, tol); }, {}, {}});
    jobs.push_back({"vern7", true, tol, [&s, tol] { return runAdaptive<N, Verner76<N>>(s, tol); }, {}, {}});
    jobs.push_back({"vern9", true, tol, [&s, tol] { return runAdaptive<N, Verner98<N>>(s, tol); }, {}, {}});
    jobs.push_back({"dop853", true, tol, [&s, tol] { return runAdaptive<N, DormandPrince853<N>>(s, tol); }, {}, {}});
    for (Peer peer : {Peer::CvodeAdams, Peer::OdeintDopri5, Peer::OdeintFehlberg78})
      jobs.push_back({peerName(peer), false, tol,
                      [&s, tol, peer] {
                        const PeerResult<N> p = runPeer<N>(peer, *s.system, s.x0, s.horizon, tol);
                        return RunResult<N>{
                            p.ok ? p.x : StateVector<N>::Constant(std::numeric_limits<double>::quiet_NaN()),
                            p.evaluations};
                      },
                      {},
                      {}});
  }
  return jobs;
}

// The reference, the fixed-step methods over the steps, then the adaptive
// methods, ours and the peers', over the tolerances, each point's error
// against the reference and its CPU time.
template <int N>
void study(const Settings& settings, const Scenario<N>& s, std::vector<WorkPoint>& points,
           std::vector<ReferenceCheck>& refs) {
  std::fprintf(stderr, "work_precision: %s (T = %g s)\n", s.name.c_str(), s.horizon);
  double floor = 0.0;
  const StateVector<N> ref = referenceOf<N>(s, refs, floor);
  auto add = [&](const std::string& method, bool ours, const char* parameter, double value, const RunResult<N>& r,
                 double seconds) {
    const double e = errorOf<N>(r.x, ref);
    points.push_back({s.name, method, ours, parameter, value, e, seconds, r.evaluations, e > floor});
  };

  const std::vector<double> steps =
      settings.quick ? std::vector<double>{4e-3, 1e-3} : std::vector<double>{1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4};
  double sec = 0.0;
  for (double h : steps) {
    RunResult<N> r = timed(settings, [&] { return runFixed<N, RungeKutta4<N>>(s, h); }, sec);
    add("rk4", true, "h", h, r, sec);
  }
  for (double h : steps) {
    RunResult<N> r = timed(settings, [&] { return runFixed<N, GaussLegendre2<N>>(s, h); }, sec);
    add("gauss2", true, "h", h, r, sec);
  }
  for (double h : steps) {
    if (h < 2e-4) continue;  // gauss3 reaches round-off error before that
    RunResult<N> r = timed(settings, [&] { return runFixed<N, GaussLegendre3<N>>(s, h); }, sec);
    add("gauss3", true, "h", h, r, sec);
  }
  // The adaptive methods, ours and the peers', are timed interleaved: for
  // each tol all six in turn, and the whole sweep in three passes (each
  // point's time the median of its passes' medians). On a shared machine a
  // burst of load then lands on every method alike instead of on one
  // method's curve.
  const std::vector<std::pair<std::string, bool>> adaptive = {
      {"dopri5", true}, {"tsit5", true}, {"vern7", true}, {"vern9", true}, {"dop853", true}, {peerName(Peer::CvodeAdams), false},
      {peerName(Peer::OdeintDopri5), false}, {peerName(Peer::OdeintFehlberg78), false}};
  std::vector<AdaptiveJob<N>> jobs = adaptiveJobs<N>(s, tolerances(settings.quick));
  const int passes = settings.quick ? 1 : 3;
  Settings perPass = settings;
  perPass.targetSeconds = settings.targetSeconds / passes;
  for (int pass = 0; pass < passes; ++pass)
    for (AdaptiveJob<N>& job : jobs) {
      job.result = timed(perPass, job.run, sec);
      job.seconds.push_back(sec);
    }
  for (const auto& [method, ours] : adaptive)
    for (AdaptiveJob<N>& job : jobs) {
      if (job.method != method) continue;
      std::nth_element(job.seconds.begin(), job.seconds.begin() + job.seconds.size() / 2, job.seconds.end());
      add(job.method, job.ours, "tol", job.tol, job.result, job.seconds[job.seconds.size() / 2]);
    }
}

template <class Method>
DriftRow tetherDrift(const char* name, double hours) {
  const Tether tether = makeTether();
  Method method;
  const double h = 1e-3;
  const long long perSecond = 1000;
  const long long seconds = std::llround(hours * 3600.0);
  ForceDrivenState x = tether.x0;
  const double h0 = tether.invariant(x);
  DriftRow row{name, h, hours, 0.0, 0.0, 0.0, 0.0, 0.0, h0};
  // Least squares of (H - H0) against t in hours, accumulated on the fly.
  double sumT = 0, sumY = 0, sumTT = 0, sumTY = 0;
  const double start = cpuNow();
  for (long long s = 1; s <= seconds; ++s) {
    for (long long i = 0; i < perSecond; ++i)
      method.step(*tether.system, static_cast<double>((s - 1) * perSecond + i) * h, x, h);
    const double dev = tether.invariant(x) - h0;
    row.maxDeviation = std::max(row.maxDeviation, std::abs(dev));
    if (s <= 360) row.firstHourTenth = row.maxDeviation;
    const double t = static_cast<double>(s) / 3600.0;
    sumT += t, sumY += dev, sumTT += t * t, sumTY += t * dev;
    row.finalDeviation = dev;
  }
  row.seconds = cpuNow() - start;
  const double n = static_cast<double>(seconds);
  row.slopePerHour = (n * sumTY - sumT * sumY) / (n * sumTT - sumT * sumT);
  std::fprintf(stderr, "work_precision: tether %s, %.3g h: max |dH| %.2e J, drift %.2e J/h, %.1f s CPU\n", name,
               hours, row.maxDeviation, row.slopePerHour, row.seconds);
  return row;
}

}  // namespace
}  // namespace hemiroll::tools

int main(int argc, char** argv) {
  using namespace hemiroll::tools;
  Settings settings;
  std::string outDir = "docs/work-precision", doc = "docs/WORK_PRECISION.md";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") {
      settings.quick = true;
    } else if (a == "--only" && i + 1 < argc) {
      settings.only = argv[++i];
    } else if (a == "--out" && i + 1 < argc) {
      outDir = argv[++i];
    } else if (a == "--doc" && i + 1 < argc) {
      doc = argv[++i];
    } else {
      std::fprintf(stderr, "usage: work_precision [--quick] [--only SCENARIO] [--out DIR] [--doc FILE.md]\n");
      return 2;
    }
  }
  const ScenarioSet scenarios(settings.quick);
  std::vector<WorkPoint> points;
  std::vector<ReferenceCheck> refs;
  std::vector<std::string> names;
  for (const auto& s : scenarios.forceDriven()) {
    if (!settings.only.empty() && s.name != settings.only) continue;
    study<12>(settings, s, points, refs);
    names.push_back(s.name);
  }
  for (const auto& s : scenarios.prescribed()) {
    if (!settings.only.empty() && s.name != settings.only) continue;
    study<8>(settings, s, points, refs);
    names.push_back(s.name);
  }
  const double hours = settings.quick || !settings.only.empty() ? 10.0 / 3600.0 : 1.0;
  std::vector<DriftRow> drift;
  drift.push_back(tetherDrift<hemiroll::physics::RungeKutta4<12>>("rk4", hours));
  drift.push_back(tetherDrift<hemiroll::physics::GaussLegendre2<12>>("gauss2", hours));
  drift.push_back(tetherDrift<hemiroll::physics::GaussLegendre3<12>>("gauss3", hours));

  const std::string csv = outDir + "/work_precision.csv";
  writeCsv(csv, points);
  writeDriftCsv(outDir + "/energy_drift.csv", drift);
  writeGnuplot(outDir + "/work_precision.gp", csv, outDir + "/work_precision.png", names, points);
  writeMarkdown(doc, points, refs, drift, settings.quick);
  std::FILE* check = std::fopen(csv.c_str(), "r");
  if (!check) {
    std::fprintf(stderr, "work_precision: cannot write %s\n", csv.c_str());
    return 1;
  }
  std::fclose(check);
  int status = 0;
  for (const ReferenceCheck& r : refs) {
    std::fprintf(stderr, "work_precision: reference check %s: %.1e\n", r.scenario.c_str(), r.disagreement);
    if (!(r.disagreement < 1e-9)) {
      std::fprintf(stderr, "work_precision: %s: references disagree (%.1e): outside the predictability window\n",
                   r.scenario.c_str(), r.disagreement);
      status = 1;
    }
  }
  return status;
}
