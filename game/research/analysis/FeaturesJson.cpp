#include "game/research/analysis/FeaturesJson.h"

#include <nlohmann/json.hpp>

namespace hemiroll::game {

namespace {

using nlohmann::json;

json interval(const analysis::TimeInterval& i) { return json::array({i.start, i.end}); }

json phasesJson(const analysis::Phases& p) {
  json j{{"found", p.found}};
  if (!p.found) {
    j["reason"] = p.reason;
    return j;
  }
  j["acceleration_s"] = interval(p.acceleration);
  j["steady_s"] = interval(p.steady);
  j["deceleration_s"] = interval(p.deceleration);
  j["steady_duration_s"] = p.steady.duration();
  j["steady_rate_rad_per_s"] = p.steadyRate;
  j["steady_rate_median_rad_per_s"] = p.steadyRateMedian;
  j["steady_rate_spread_rad_per_s"] = p.steadyRateSpread;
  return j;
}

json roseJson(const analysis::RoseFeatures& r, const analysis::TimeInterval& window, const std::string& note) {
  json j{{"found", r.found}, {"window_s", interval(window)}, {"tone_share", r.toneShare}};
  if (!note.empty()) j["note"] = note;
  if (!r.found) {
    j["reason"] = r.reason;
    return j;
  }
  j["leaves"] = r.leaves;
  j["leaves_per_cycle"] = r.leavesPerCycle;
  j["leaves_per_cycle_spread"] = r.leavesPerCycleSpread;
  j["leaves_per_closed_cycle"] = r.leavesPerClosedCycle;
  j["leaf_radius_m"] = r.leafRadius.value;
  j["leaf_radius_spread_m"] = r.leafRadius.spread;
  j["outer_radius_m"] = r.outerRadius.value;
  j["outer_radius_spread_m"] = r.outerRadius.spread;
  j["inner_radius_m"] = r.innerRadius.value;
  j["inner_radius_spread_m"] = r.innerRadius.spread;
  j["leaf_period_s"] = r.leafPeriod.value;
  j["leaf_period_spread_s"] = r.leafPeriod.spread;
  j["span_s"] = interval(r.span);
  j["span_duration_s"] = r.span.duration();
  j["leaf_count"] = r.leafCount;
  j["cycles"] = r.cycles;
  j["sense"] = r.sense > 0 ? "counter-clockwise" : "clockwise";
  j["centre_m"] = json::array({r.centreX, r.centreY});
  j["confidence"] = r.confidence;
  return j;
}

json helixJson(const analysis::HelixFeatures& h, const analysis::TimeInterval& window, const std::string& note) {
  json j{{"window_s", interval(window)}};
  if (!note.empty()) j["note"] = note;
  const analysis::ArcFeatures& a = h.arc;
  json arc{{"found", a.found}, {"length_m", a.length}, {"drift_speed_m_per_s", a.driftSpeed},
           {"curvature_per_m", a.curvature}, {"curvature_error_per_m", a.curvatureError},
           {"rms_residual_m", a.rmsResidual}, {"span_s", interval(a.span)}};
  if (a.found) {
    arc["radius_m"] = a.radius;
    arc["centre_m"] = json::array({a.centreX, a.centreY});
    arc["swept_angle_rad"] = a.sweptAngle;
  } else {
    arc["reason"] = a.reason;
  }
  const analysis::LoopFeatures& l = h.loops;
  json loops{{"found", l.found}, {"tone_share", l.toneShare}};
  if (l.found) {
    loops["count"] = l.count;
    loops["frequency_Hz"] = l.frequency;
    loops["sense"] = l.sense > 0 ? "counter-clockwise" : "clockwise";
    loops["spacing_s"] = l.spacingTime.value;
    loops["spacing_spread_s"] = l.spacingTime.spread;
    loops["spacing_m"] = l.spacingArc.value;
    loops["spacing_spread_m"] = l.spacingArc.spread;
    loops["times_s"] = l.times;
  } else {
    loops["reason"] = l.reason;
  }
  j["arc"] = arc;
  j["loops"] = loops;
  return j;
}

}  // namespace

std::string featuresJson(const TrialData& trial, const analysis::TrialFeatures& f,
                         const analysis::GuidanceWork& guidance) {
  json j;
  j["format"] = "hemiroll-analysis";
  j["format_version"] = 1;
  j["trial"] = trial.id;
  j["source"] = trial.source;
  j["kind"] = trial.kind;
  j["notes"] = trial.notes;
  j["samples"] = trial.time.size();
  j["duration_s"] = f.phases.trial.duration();
  j["phases"] = phasesJson(f.phases);
  j["rose"] = roseJson(f.rose, f.roseWindow, f.roseNote);
  j["helix"] = helixJson(f.helix, f.helixWindow, f.helixNote);
  if (f.loopsPerLeaf > 0.0) j["loops_per_leaf"] = f.loopsPerLeaf;
  if (guidance.present)
    j["guidance"] = {{"work_J", guidance.work},
                     {"opposed_share", guidance.opposedShare},
                     {"guided_time_s", guidance.guidedTime}};
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace hemiroll::game
