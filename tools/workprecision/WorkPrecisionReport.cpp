#include "tools/workprecision/WorkPrecisionReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace hemiroll::tools {

namespace {

constexpr double kLevels[] = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};

std::vector<std::string> methodsOf(const std::vector<WorkPoint>& points, bool ours) {
  std::vector<std::string> out;
  for (const WorkPoint& p : points)
    if (p.ours == ours && std::find(out.begin(), out.end(), p.method) == out.end()) out.push_back(p.method);
  return out;
}

std::vector<WorkPoint> curve(const std::vector<WorkPoint>& points, const std::string& scenario,
                             const std::string& method) {
  std::vector<WorkPoint> out;
  for (const WorkPoint& p : points)
    if (p.scenario == scenario && p.method == method && p.reliable && std::isfinite(p.error) && p.error > 0.0)
      out.push_back(p);
  return out;
}

std::vector<std::string> scenariosOf(const std::vector<WorkPoint>& points) {
  std::vector<std::string> out;
  for (const WorkPoint& p : points)
    if (std::find(out.begin(), out.end(), p.scenario) == out.end()) out.push_back(p.scenario);
  return out;
}

}  // namespace

CostAtError costAtError(const std::vector<WorkPoint>& c, double e) {
  CostAtError best;
  const double le = std::log(e);
  for (std::size_t i = 0; i + 1 < c.size(); ++i) {
    const double l0 = std::log(c[i].error), l1 = std::log(c[i + 1].error);
    if ((le - l0) * (le - l1) > 0.0) continue;  // not bracketed
    const double w = l1 == l0 ? 0.0 : (le - l0) / (l1 - l0);
    auto between = [w](double a, double b) { return std::exp((1.0 - w) * std::log(a) + w * std::log(b)); };
    const double t = between(c[i].seconds, c[i + 1].seconds);
    if (best.seconds < 0.0 || t < best.seconds)
      best = {t, between(static_cast<double>(c[i].evaluations), static_cast<double>(c[i + 1].evaluations))};
  }
  return best;
}

double timeAtError(const std::vector<WorkPoint>& c, double e) { return costAtError(c, e).seconds; }

namespace {

// Why the margin over the best peer is what it is: evaluations per error
// and CPU time per evaluation, ours against the peers', at every level.
void writeEvaluationAccount(std::FILE* f, const std::vector<WorkPoint>& points) {
  const std::vector<std::string> ours = methodsOf(points, true);
  const char* const peers[] = {"odeint-rkf78", "odeint-dopri5", "cvode-adams"};
  std::fprintf(f,
               "## Why the margin over RKF78 is not 2x: evaluations per error\n\n"
               "Every method calls the same right-hand side, so a method's CPU time is its evaluations times "
               "(the right-hand side + its own work per evaluation). Below, at each error: our fastest method's "
               "evaluations and CPU time per evaluation, and each peer's evaluations as a multiple of ours and its "
               "time per evaluation. The last column is CVODE's evaluations over RKF78's.\n\n"
               "| scenario | error | our best | evaluations | ns/eval | rkf78 evals x | rkf78 ns/eval | dopri5 evals x | "
               "dopri5 ns/eval | cvode evals x | cvode ns/eval | cvode / rkf78 evals |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  double minRkf = 1e300, maxRkf = 0.0, minCvode = 1e300, maxCvode = 0.0, maxOverhead = 0.0;
  double minCvodeWork = 1e300, maxCvodeWork = 0.0;  // CVODE's time per evaluation over ours
  for (const std::string& s : scenariosOf(points)) {
    for (double level : kLevels) {
      CostAtError best;
      std::string bestMethod;
      for (const std::string& m : ours) {
        const CostAtError c = costAtError(curve(points, s, m), level);
        if (c.seconds > 0.0 && (best.seconds < 0.0 || c.seconds < best.seconds)) {
          best = c;
          bestMethod = m;
        }
      }
      if (best.seconds < 0.0) continue;
      std::fprintf(f, "| %s | %.0e | %s | %.0f | %.0f |", s.c_str(), level, bestMethod.c_str(), best.evaluations,
                   1e9 * best.seconds / best.evaluations);
      CostAtError peerCost[3];
      for (int i = 0; i < 3; ++i) {
        peerCost[i] = costAtError(curve(points, s, peers[i]), level);
        if (peerCost[i].seconds > 0.0)
          std::fprintf(f, " %.2f | %.0f |", peerCost[i].evaluations / best.evaluations,
                       1e9 * peerCost[i].seconds / peerCost[i].evaluations);
        else
          std::fprintf(f, " - | - |");
      }
      if (peerCost[0].seconds > 0.0) {
        const double rkf = peerCost[0].evaluations / best.evaluations;
        minRkf = std::min(minRkf, rkf);
        maxRkf = std::max(maxRkf, rkf);
        const double perEvalOurs = best.seconds / best.evaluations, perEvalRkf = peerCost[0].seconds / peerCost[0].evaluations;
        maxOverhead = std::max(maxOverhead, std::abs(perEvalRkf / perEvalOurs - 1.0));
      }
      if (peerCost[0].seconds > 0.0 && peerCost[2].seconds > 0.0) {
        const double cvode = peerCost[2].evaluations / peerCost[0].evaluations;
        minCvode = std::min(minCvode, cvode);
        maxCvode = std::max(maxCvode, cvode);
        const double work = (peerCost[2].seconds / peerCost[2].evaluations) / (best.seconds / best.evaluations);
        minCvodeWork = std::min(minCvodeWork, work);
        maxCvodeWork = std::max(maxCvodeWork, work);
        std::fprintf(f, " %.2f |\n", cvode);
      } else {
        std::fprintf(f, " - |\n");
      }
    }
  }
  std::fprintf(
      f,
      "\n**The account.** Our methods and odeint's spend the same CPU time per evaluation (the two differ by "
      "at most %.0f%% at any level here): nearly all of it is the right-hand side, which both call. So the time "
      "ratio over RKF78 is its evaluation ratio, and RKF78 needs %.2f to %.2f times our best method's "
      "evaluations: a 2x margin would need half of them at every level. Our best are DOP853 and Verner's "
      "pairs chosen by him as the most efficient of their orders. The other way to fewer evaluations is a "
      "multistep method: CVODE's variable-order Adams needs "
      "%.2f to %.2f times RKF78's evaluations, so even an Adams method with no work of its own "
      "per step would not be 2x faster than RKF78 at every level (CVODE itself spends %.0f to %.0f times our "
      "time per evaluation). A cheaper right-hand side does not change the ratio either, because "
      "the peers call the same one; and running many trajectories in SIMD lanes (BatchedRk4.h) speeds a "
      "sweep, not one trajectory. What could change the count is a method whose steps are not made of "
      "right-hand-side evaluations, a Taylor series method by automatic differentiation; it is not built, "
      "and nothing here measures whether it would pay.\n\n",
      100.0 * maxOverhead, minRkf, maxRkf, minCvode, maxCvode, minCvodeWork, maxCvodeWork);
}

}  // namespace

void writeCsv(const std::string& path, const std::vector<WorkPoint>& points) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return;
  std::fprintf(f, "scenario,method,kind,parameter,value,error,cpu_seconds,rhs_evaluations,reliable\n");
  for (const WorkPoint& p : points)
    std::fprintf(f, "%s,%s,%s,%s,%.6g,%.6e,%.6e,%lld,%d\n", p.scenario.c_str(), p.method.c_str(),
                 p.ours ? "ours" : "peer", p.parameter.c_str(), p.value, p.error, p.seconds, p.evaluations,
                 p.reliable ? 1 : 0);
  std::fclose(f);
}

void writeDriftCsv(const std::string& path, const std::vector<DriftRow>& rows) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return;
  std::fprintf(f, "method,h,hours,invariant0_J,max_abs_deviation_J,max_abs_deviation_first_6min_J,final_deviation_J,"
                  "slope_J_per_hour,cpu_seconds\n");
  for (const DriftRow& r : rows)
    std::fprintf(f, "%s,%.6g,%.6g,%.12g,%.6e,%.6e,%.6e,%.6e,%.3f\n", r.method.c_str(), r.step, r.hours, r.invariant0,
                 r.maxDeviation, r.firstHourTenth, r.finalDeviation, r.slopePerHour, r.seconds);
  std::fclose(f);
}

void writeGnuplot(const std::string& scriptPath, const std::string& csvPath, const std::string& pngPath,
                  const std::vector<std::string>& scenarios, const std::vector<WorkPoint>& points) {
  std::FILE* f = std::fopen(scriptPath.c_str(), "w");
  if (!f) return;
  std::fprintf(f,
               "# Generated by work_precision: log error against log CPU time, one curve per method.\n"
               "set terminal pngcairo size 1800,1100 font ',10'\n"
               "set output '%s'\n"
               "set datafile separator ','\n"
               "set logscale xy\nset format x '10^{%%L}'\nset format y '10^{%%L}'\n"
               "set xlabel 'error at the horizon (max norm, SI)'\nset ylabel 'CPU time [s]'\n"
               "set grid\nset key top right font ',8'\n"
               "set multiplot layout 2,3 title 'hemiroll work-precision (ours: solid; peers: dashed)'\n",
               pngPath.c_str());
  std::vector<std::string> methods = methodsOf(points, true), peers = methodsOf(points, false);
  for (const std::string& s : scenarios) {
    std::fprintf(f, "set title '%s'\nplot ", s.c_str());
    bool first = true;
    int colour = 1;
    for (const std::string& m : methods) {
      std::fprintf(f, "%s'%s' using (strcol(1) eq '%s' && strcol(2) eq '%s' && $9 == 1 ? $6 : NaN):7 "
                      "with linespoints lw 2 pt 7 lc %d title '%s'",
                   first ? "" : ", \\\n  ", csvPath.c_str(), s.c_str(), m.c_str(), colour++, m.c_str());
      first = false;
    }
    for (const std::string& m : peers) {
      std::fprintf(f, ", \\\n  '%s' using (strcol(1) eq '%s' && strcol(2) eq '%s' && $9 == 1 ? $6 : NaN):7 "
                      "with linespoints lw 2 dt 2 pt 6 lc %d title '%s'",
                   csvPath.c_str(), s.c_str(), m.c_str(), colour++, m.c_str());
    }
    std::fprintf(f, "\n");
  }
  std::fprintf(f, "unset multiplot\n");
  std::fclose(f);
}

namespace {

// The page's head: what is measured, how, and against whom.
void writeMethodNote(std::FILE* f, bool quick) {
  std::fprintf(f,
               "# Work-precision: run time against error\n\n"
               "Generated by `make bench` (tools/run-benchmarks.sh -> build/bench/work_precision)%s; do not edit by "
               "hand.\nData: [work-precision/work_precision.csv](work-precision/work_precision.csv), diagram: "
               "[work-precision/work_precision.png](work-precision/work_precision.png), invariant table: "
               "[work-precision/energy_drift.csv](work-precision/energy_drift.csv).\n\n"
               "![work-precision diagram](work-precision/work_precision.png)\n\n"
               "**Method.** Every method integrates the same right-hand side (`OdeSystem<N>::derivative`, one virtual "
               "call per evaluation, peers through a thin copy-in/copy-out adapter) from t = 0 to the horizon T. "
               "Error: max over the state's components of |x_i(T) - x_ref,i(T)|, each in its own SI unit (m, m/s, "
               "rad, rad/s). Reference: our DOP853 with the state in long double (`dop853ld`) at tol 1e-16; a second "
               "reference at tol 1e-15 checks it (their disagreement bounds the error of the looser one), and points "
               "with error below 10x that disagreement are marked unreliable and left out. CPU time: thread CPU time, median of repeated runs (at least 3, more for "
               "short runs); the adaptive methods, ours and the peers', timed interleaved (at each tol all six in "
               "turn) in three passes over the sweep, the median of the passes taken, so that load from other "
               "work on the machine falls on all curves alike. Ours: rk4, gauss2, gauss3 (fixed step h), dopri5, tsit5 (Tsitouras 2011), vern7 and vern9 (Verner 2010), dop853 (tolerance sweep "
               "1, 2, 5 per decade from 1e-3 to 1e-14, atol = rtol = tol, to the end state only: no dense output is "
               "asked for, so DOP853's three dense-output stages are never computed). Peers, on the same tolerance "
               "grid: SUNDIALS CVODE 6.4.1 (Adams, functional iteration, CVodeSStolerances(tol, tol), stop time T, "
               "otherwise its defaults: max order 12, its own initial step), Boost.Odeint 1.74 "
               "runge_kutta_dopri5 and runge_kutta_fehlberg78 (integrate_adaptive with the controlled stepper of "
               "make_controlled(tol, tol), i.e. default_error_checker with a_x = a_dxdt = 1, starting at dt = 1e-4 "
               "and left to its own step control).\n\n",
               quick ? " in --quick mode (short horizons, few points: NOT the published figures)" : "");
}

// The references' agreement per scenario (the predictability window).
void writeReferences(std::FILE* f, const std::vector<ReferenceCheck>& references) {
  std::fprintf(f, "## References and the predictability window\n\n"
                  "| scenario | horizon [s] | ref(1e-16) vs ref(1e-15) | reference CPU [s] |\n|---|---|---|---|\n");
  for (const ReferenceCheck& r : references)
    std::fprintf(f, "| %s | %.3g | %.1e | %.3f |\n", r.scenario.c_str(), r.horizon, r.disagreement, r.seconds);
}

// Per scenario and error level, our fastest method against each peer, then
// each peer's narrowest ratio and lost comparisons.
void writePeerComparison(std::FILE* f, const std::vector<WorkPoint>& points) {
  const std::vector<std::string> ours = methodsOf(points, true), peers = methodsOf(points, false);
  std::fprintf(f, "\n## Our best method against each peer\n\n"
                  "CPU time of the peer divided by the CPU time of our fastest method at the same error (each curve "
                  "interpolated in log-log; > 1: ours is faster). '-' where a curve does not reach that error.\n\n");
  std::map<std::string, double> worst;  // peer -> smallest ratio seen
  std::map<std::string, int> losses;
  for (const std::string& s : scenariosOf(points)) {
    std::fprintf(f, "### %s\n\n| error | our best | time [s] |", s.c_str());
    for (const std::string& p : peers) std::fprintf(f, " %s |", p.c_str());
    std::fprintf(f, "\n|---|---|---|");
    for (std::size_t i = 0; i < peers.size(); ++i) std::fprintf(f, "---|");
    std::fprintf(f, "\n");
    for (double level : kLevels) {
      double bestTime = -1.0;
      std::string bestMethod = "-";
      for (const std::string& m : ours) {
        const double t = timeAtError(curve(points, s, m), level);
        if (t > 0.0 && (bestTime < 0.0 || t < bestTime)) {
          bestTime = t;
          bestMethod = m;
        }
      }
      std::fprintf(f, "| %.0e | %s | %s |", level, bestMethod.c_str(),
                   bestTime > 0.0 ? (std::to_string(bestTime).substr(0, 9)).c_str() : "-");
      for (const std::string& p : peers) {
        const double t = timeAtError(curve(points, s, p), level);
        if (t > 0.0 && bestTime > 0.0) {
          const double ratio = t / bestTime;
          std::fprintf(f, " %.2f |", ratio);
          if (!worst.count(p) || ratio < worst[p]) worst[p] = ratio;
          if (ratio < 1.0) ++losses[p];
        } else {
          std::fprintf(f, " - |");
        }
      }
      std::fprintf(f, "\n");
    }
    std::fprintf(f, "\n");
  }
  std::fprintf(f, "**Summary.** ");
  for (const std::string& p : peers)
    std::fprintf(f, "Against %s: smallest ratio %.2f, %d comparison(s) lost. ", p.c_str(),
                 worst.count(p) ? worst[p] : 0.0, losses[p]);
  std::fprintf(f, "\n\n");
}

// Why the margins are what they are (measured once, written out).
void writeMarginNote(std::FILE* f) {
  std::fprintf(
      f,
      "**Where the margins come from.** CVODE Adams needs no more evaluations than DOP853 for an error (often "
      "fewer), but on an 8- or 12-state problem its own per-step work (order and step selection on the "
      "Nordsieck history, the fixed-point iteration, N_Vector operations) dominates: about 1.7 us of run "
      "time per evaluation on m3moving at tol 1e-8, against 0.15 us for ours (see the CSV's rhs_evaluations). "
      "odeint's DOPRI5 is a 5th-order method. Against odeint's RKF78 the margin is smaller: both are "
      "8th-order and the right-hand side is about 80%% of both runs, so the ratio is mostly evaluations per "
      "error. DOP853 takes 12 evaluations per step (the 13th is the next step's first) against 13, and needs "
      "fewer evaluations for the same error; the bookkeeping per evaluation is about the same (counted "
      "with callgrind on the rose: about 150 instructions per "
      "evaluation for ours, 170 for odeint's). DOP853 computes the dense output's three extra stages only "
      "when interpolate() is called (the work-precision runs never call it, as odeint's never interpolate). "
      "What was changed to win against RKF78: DOP853 no longer copies the accepted step's 13 stages (two "
      "banks that swap), forms each stage and the error norm in one pass over the components, the step "
      "control takes one log and one exp per step instead of two pow, and DOP853 "
      "uses the stabilized (PI) step control that Hairer's DOP853 offers as an option, beta = 0.04, instead "
      "of its default beta = 0: with beta = 0, 8 "
      "to 22%% of the steps were rejected (11 evaluations each, thrown away), with 0.04 1 to 10%%. The "
      "narrowest margin is the paper's rose near 1e-8 against RKF78 (a few per cent, repeatable on a quiet "
      "machine, but no larger than a burst of load from other work): there the end-point error of both "
      "methods stays flat over a decade of tol, and DOP853 needs only about 4%% fewer evaluations.\n\n");
}

// The undamped tether's invariant over the long horizon.
void writeDrift(std::FILE* f, const std::vector<DriftRow>& drift) {
  std::fprintf(f, "## Long-horizon invariant: the undamped tether\n\n"
                  "M2 spring (k_r = 250 N/m, k_v = 0) to a fixed proxy; H = E + (1/2) k_r |r_p - r_h|^2 is "
                  "conserved exactly, so its change is the integrator's. Sampled every simulated second.\n\n"
                  "| method | h [s] | simulated [h] | H(0) [J] | max abs(H - H0), first 6 min [J] | "
                  "max abs(H - H0) [J] | H(T) - H0 [J] | fitted drift [J/h] | CPU [s] |\n"
                  "|---|---|---|---|---|---|---|---|---|\n");
  for (const DriftRow& r : drift)
    std::fprintf(f, "| %s | %.0e | %.3g | %.6f | %.2e | %.2e | %.2e | %.2e | %.2f |\n", r.method.c_str(), r.step,
                 r.hours, r.invariant0, r.firstHourTenth, r.maxDeviation, r.finalDeviation, r.slopePerHour,
                 r.seconds);
  std::fprintf(f, "\nA drifting method shows max abs(H - H0) growing with the run and a fitted drift that explains "
                  "it; a symmetric method shows a deviation that does not grow past its first minutes.\n");
}

}  // namespace

void writeMarkdown(const std::string& path, const std::vector<WorkPoint>& points,
                   const std::vector<ReferenceCheck>& references, const std::vector<DriftRow>& drift, bool quick) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return;
  writeMethodNote(f, quick);
  writeReferences(f, references);
  writePeerComparison(f, points);
  writeMarginNote(f);
  writeEvaluationAccount(f, points);
  writeDrift(f, drift);
  std::fclose(f);
}

}  // namespace hemiroll::tools
