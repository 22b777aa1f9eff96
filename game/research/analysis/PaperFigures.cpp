#include "game/research/analysis/PaperFigures.h"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "game/research/analysis/FeaturesJson.h"
#include "game/research/analysis/TrialPlots.h"

namespace hemiroll::game {

namespace {

std::string fixed(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, std::isfinite(v) ? v : 0.0);
  return buffer;
}

std::string cm(const analysis::Estimate& e) { return fixed(100.0 * e.value, 2) + " ± " + fixed(100.0 * e.spread, 2) + " cm"; }

std::string row(const std::string& feature, const std::string& paper, const std::string& measured) {
  return "| " + feature + " | " + paper + " | " + measured + " |\n";
}

}  // namespace

std::string paperFiguresMarkdown(const FigureRun& run, const analysis::TrialFeatures& f) {
  const physics::RoseDef& d = run.rose;
  const analysis::RoseFeatures& r = f.rose;
  const analysis::ArcFeatures& a = f.helix.arc;
  const analysis::LoopFeatures& l = f.helix.loops;
  const analysis::Phases& p = f.phases;
  std::string md = "Run: " + run.trial.source + ", prescribed rose drive (8 states, eqs. 46-48), r1 = " + fixed(100 * d.r1, 2) +
                   " cm, r2 = " + fixed(100 * d.r2, 2) + " cm, k = " + fixed(d.k, 2) + ", Omega = " + fixed(d.omega, 4) +
                   " rad/s, " + fixed(p.trial.duration(), 3) + " s at h = " + fixed(1000 * run.timeStep, 3) + " ms (" +
                   run.integrator + "), starting " + run.start +
                   (run.event.empty() ? "" : ", stopped by the event " + run.event) + ".\n\n";
  md += "| feature | the paper | measured on this run |\n|---|---|---|\n";
  md += row("leaves per closed cycle (mass point)", "k + 1 = " + fixed(d.k + 1, 0) + " (human: 8-15)",
            r.found ? std::to_string(r.leaves) + " (" + fixed(r.leavesPerCycle, 3) + " ± " + fixed(r.leavesPerCycleSpread, 3) + ")"
                    : "not found: " + r.reason);
  if (r.found) {
    md += row("leaf radius", "r2 = " + fixed(100 * d.r2, 2) + " cm (human: 0.4-1.0 cm)", cm(r.leafRadius));
    md += row("outer radius", "r1 + r2 = " + fixed(100 * (d.r1 + d.r2), 2) + " cm (human: 1.2-2.4 cm)", cm(r.outerRadius));
    md += row("time span of the rose", "35 s simulated (human: 18-32 s)",
              fixed(r.span.duration(), 1) + " s (" + fixed(r.span.start, 1) + "-" + fixed(r.span.end, 1) + " s, " +
                  std::to_string(r.leafCount) + " leaves)");
  }
  md += row("steady precession", "psi' nearly constant after the initial imbalance (Fig. 11)",
            p.found ? fixed(p.steady.start, 1) + "-" + fixed(p.steady.end, 1) + " s at " + fixed(p.steadyRate, 3) +
                          " ± " + fixed(p.steadyRateSpread, 3) + " rad/s"
                    : "not found: " + p.reason);
  md += row("curvature of the contact trace", "circularly curved (Fig. 10)",
            a.found ? fixed(a.curvature, 1) + " ± " + fixed(a.curvatureError, 2) + " 1/m (radius " +
                          fixed(100 * a.radius, 2) + " cm, rms " + fixed(1000 * a.rmsResidual, 2) + " mm)"
                    : a.reason);
  md += row("loops along the trace", "spiral-like loops, conjectured one per leaf",
            l.found ? std::to_string(l.count) + " loops every " + fixed(l.spacingTime.value, 2) + " ± " +
                          fixed(l.spacingTime.spread, 2) + " s" +
                          (f.loopsPerLeaf > 0.0 ? ", " + fixed(f.loopsPerLeaf, 2) + " loops per leaf" : "")
                    : l.reason);
  md += row("drift of the contact point", "-", fixed(1000 * a.driftSpeed, 2) + " mm/s over " + fixed(100 * a.length, 1) + " cm");
  if (!f.roseNote.empty()) md += "\nRose: " + f.roseNote + ".\n";
  if (!f.helixNote.empty()) md += "\nHelix: " + f.helixNote + ".\n";
  return md;
}

OutputFiles paperFigures(const FigureRun& run, const analysis::TrialFeatures& f) {
  OutputFiles files;
  report::LinePlotDef fig9 = massPointPlot(run.trial, f);
  fig9.title = "Fig. 9: roselike trajectory of the mass point";
  report::LinePlotDef fig10 = contactTracePlot(run.trial, f);
  fig10.title = "Fig. 10: trajectory of the contact point";
  report::LinePlotDef fig11 = precessionAnglePlot(run.trial, f);
  fig11.title = "Fig. 11: precession angle psi";
  files.emplace_back("fig09_mass_point_rose.svg", report::renderLinePlot(fig9, 600, 560));
  files.emplace_back("fig10_contact_trajectory.svg", report::renderLinePlot(fig10, 600, 560));
  files.emplace_back("fig11_precession_angle.svg", report::renderLinePlot(fig11, 720, 420));
  nlohmann::json j = nlohmann::json::parse(featuresJson(run.trial, f));
  j["run"] = {{"drive", "rose"},           {"r1_m", run.rose.r1},          {"r2_m", run.rose.r2},
              {"k", run.rose.k},           {"Omega_rad_per_s", run.rose.omega}, {"time_step_s", run.timeStep},
              {"integrator", run.integrator}, {"start", run.start}, {"event", run.event.empty() ? nlohmann::json() : nlohmann::json(run.event)}};
  files.emplace_back("figures_features.json", j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  files.emplace_back("figures_features.md", "# Features of the `hemiroll figures` run\n\n" + paperFiguresMarkdown(run, f));
  return files;
}

}  // namespace hemiroll::game
