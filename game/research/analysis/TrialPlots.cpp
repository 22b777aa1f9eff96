#include "game/research/analysis/TrialPlots.h"

#include <cmath>
#include <cstdio>

#include "game/research/report/PlotSheet.h"

namespace hemiroll::game {

namespace {

constexpr double kCm = 100.0;  // plots show lengths in cm, as the paper does
constexpr const char* kFaint = "#b8c4d6";

// The samples of (x, y) whose time lies in the window.
report::Series within(const std::vector<double>& t, const std::vector<double>& x, const std::vector<double>& y,
                      const analysis::TimeInterval& w, std::string label, std::string colour) {
  report::Series s{std::move(label), {}, {}, std::move(colour)};
  for (std::size_t i = 0; i < t.size() && i < x.size() && i < y.size(); ++i)
    if (t[i] >= w.start && t[i] <= w.end) s.x.push_back(x[i]), s.y.push_back(y[i]);
  return s;
}

report::Series markers(std::string label, std::vector<double> x, std::vector<double> y, std::string colour) {
  report::Series s{std::move(label), std::move(x), std::move(y), std::move(colour)};
  s.markers = true;
  return s;
}

std::string fixed(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, std::isfinite(v) ? v : 0.0);
  return buffer;
}

std::vector<report::Band> phaseBands(const analysis::Phases& p) {
  if (!p.found) return {};
  return {{p.acceleration.start, p.acceleration.end, "acceleration", "#ff7f0e", 0.12},
          {p.steady.start, p.steady.end, "steady precession", "#2ca02c", 0.12},
          {p.deceleration.start, p.deceleration.end, "deceleration", "#9467bd", 0.12}};
}

// A path on a plane in cm with equal axes, drawn faint in full.
report::LinePlotDef planarPlot(std::string title, std::string xLabel, std::string yLabel, std::string pathLabel,
                               const std::vector<double>& x, const std::vector<double>& y) {
  report::LinePlotDef plot;
  plot.title = std::move(title);
  plot.x = {std::move(xLabel), kCm};
  plot.y = {std::move(yLabel), kCm};
  plot.equalAspect = true;
  plot.series.push_back({std::move(pathLabel), x, y, kFaint, 1.0});
  return plot;
}

}  // namespace

report::LinePlotDef contactTracePlot(const TrialData& trial, const analysis::TrialFeatures& f) {
  report::LinePlotDef plot =
      planarPlot("contact point on the plane", "u_a [cm]", "v_a [cm]", "trace", trial.contactX, trial.contactY);
  const analysis::HelixFeatures& h = f.helix;
  // The hand's path (the proxy), where the recording has it: what moved the
  // contact, in the same plane and scale.
  if (!trial.proxyX.empty()) plot.series.push_back({"proxy (the hand)", trial.proxyX, trial.proxyY, "#8c564b", 0.8});
  plot.series.push_back(within(trial.time, trial.contactX, trial.contactY, f.helixWindow, "analysed window", "#1f77b4"));
  if (!h.arc.x.empty()) plot.series.push_back({"low-passed", h.arc.x, h.arc.y, "#d62728", 2.0});
  if (h.arc.found) {
    report::Series circle{"fitted arc, radius " + fixed(kCm * h.arc.radius, 1) + " cm", {}, {}, "#2ca02c", 1.5};
    const double a0 = std::atan2(h.arc.y.front() - h.arc.centreY, h.arc.x.front() - h.arc.centreX);
    for (int i = 0; i <= 200; ++i) {
      const double a = a0 + h.arc.sweptAngle * i / 200.0;
      circle.x.push_back(h.arc.centreX + h.arc.radius * std::cos(a));
      circle.y.push_back(h.arc.centreY + h.arc.radius * std::sin(a));
    }
    plot.series.push_back(std::move(circle));
  }
  if (h.loops.found) plot.series.push_back(markers(std::to_string(h.loops.count) + " loops", h.loops.x, h.loops.y, "#ff7f0e"));
  return plot;
}

report::LinePlotDef massPointPlot(const TrialData& trial, const analysis::TrialFeatures& f) {
  report::LinePlotDef plot = planarPlot("mass point on the face", "x_p [cm]", "y_p [cm]", "path", trial.massX, trial.massY);
  const analysis::RoseFeatures& r = f.rose;
  if (r.found) {
    plot.series.push_back(within(trial.time, trial.massX, trial.massY, r.span,
                                 "rose: " + std::to_string(r.leaves) + " leaves, " + fixed(r.span.start, 1) + "-" +
                                     fixed(r.span.end, 1) + " s",
                                 "#1f77b4"));
    plot.series.push_back(markers("leaf tips", r.tipX, r.tipY, "#d62728"));
    plot.series.push_back(markers("centre", {r.centreX}, {r.centreY}, "#222222"));
  }
  return plot;
}

report::LinePlotDef precessionAnglePlot(const TrialData& trial, const analysis::TrialFeatures& f) {
  report::LinePlotDef plot;
  plot.title = "precession angle";
  plot.x = {"t [s]", 1.0};
  plot.y = {"psi [rad]", 1.0};
  plot.series.push_back({"psi", trial.time, trial.psi, "#1f77b4", 1.5});
  plot.bands = phaseBands(f.phases);
  return plot;
}

report::LinePlotDef precessionRatePlot(const analysis::TrialFeatures& f) {
  const analysis::Phases& p = f.phases;
  report::LinePlotDef plot;
  plot.title = "precession rate (smoothed)";
  plot.x = {"t [s]", 1.0};
  plot.y = {"psi' [rad/s]", 1.0};
  report::Series rate{"psi'", {}, p.rate, "#1f77b4", 1.5};
  for (std::size_t i = 0; i < p.rate.size(); ++i) rate.x.push_back(p.rateT0 + static_cast<double>(i) * p.rateDt);
  plot.series.push_back(std::move(rate));
  if (p.found) {
    plot.series.push_back({"steady " + fixed(p.steadyRate, 3) + " rad/s", {p.steady.start, p.steady.end},
                           {p.steadyRate, p.steadyRate}, "#2ca02c", 2.0});
  }
  plot.bands = phaseBands(p);
  return plot;
}

report::LinePlotDef channelsPlot(const TrialData& trial) {
  report::LinePlotDef plot;
  plot.title = "channels";
  plot.x = {"t [s]", 1.0};
  plot.y = {"[cm]", kCm};
  plot.series.push_back({"x_p", trial.time, trial.massX});
  plot.series.push_back({"y_p", trial.time, trial.massY});
  plot.series.push_back({"u_a", trial.time, trial.contactX});
  plot.series.push_back({"v_a", trial.time, trial.contactY});
  return plot;
}

std::string overviewSheet(const TrialData& trial, const analysis::TrialFeatures& f) {
  report::PlotSheet sheet(2, 560, 440, "hemiroll analyze: " + trial.id);
  sheet.add(contactTracePlot(trial, f));
  sheet.add(massPointPlot(trial, f));
  sheet.add(precessionAnglePlot(trial, f));
  sheet.add(precessionRatePlot(f));
  sheet.add(channelsPlot(trial));
  return sheet.svg();
}

}  // namespace hemiroll::game
