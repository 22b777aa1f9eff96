#include "game/research/sweep/SweepSpecJson.h"

#include <nlohmann/json.hpp>

#include "engine/record/ContentHash.h"
#include "game/research/sweep/SweepError.h"

namespace hemiroll::game {

namespace {

using json = nlohmann::ordered_json;  // keys in the order written: the canonical text

json toJson(const task::SweepDef& d) {
  json axes = json::array();
  for (const task::SweepAxis& a : d.axes)
    axes.push_back({{"param", task::sweepParamInfo(a.param).name}, {"values", a.values}, {"log", a.log}});
  return {{"params", {{"R_m", d.params.radius}, {"m_s_kg", d.params.shellMass}, {"m_p_kg", d.params.pointMass},
                      {"g_m_per_s2", d.params.gravity}}},
          {"drive", {{"r1_m", d.rose.r1}, {"r2_m", d.rose.r2}, {"k", d.rose.k}, {"Omega_rad_per_s", d.rose.omega}}},
          {"start", task::sweepStartName(d.start)},
          {"duration_s", d.duration},
          {"dt_s", d.timeStep},
          {"integrator", d.integrator},
          {"tol", d.tolerance},
          {"analysis", {{"min_rate_rad_per_s", d.analysis.minRate}, {"relative_band", d.analysis.relativeBand},
                        {"absolute_band_rad_per_s", d.analysis.absoluteBand},
                        {"min_steady_fraction", d.analysis.minSteadyFraction},
                        {"max_relative_spread", d.analysis.maxRelativeSpread}}},
          {"axes", axes}};
}

}  // namespace

std::string specJson(const task::SweepDef& def) { return toJson(def).dump(); }

std::string specHash(const task::SweepDef& def) { return record::contentHash(specJson(def)); }

task::SweepDef specFromJson(const std::string& text, const std::string& where) {
  task::SweepDef d;
  try {
    const json j = json::parse(text);
    const json& p = j.at("params");
    d.params = {p.at("R_m").get<double>(), p.at("m_s_kg").get<double>(), p.at("m_p_kg").get<double>(),
                p.at("g_m_per_s2").get<double>()};
    const json& r = j.at("drive");
    d.rose = {r.at("r1_m").get<double>(), r.at("r2_m").get<double>(), r.at("k").get<double>(),
              r.at("Omega_rad_per_s").get<double>()};
    const std::string start = j.at("start").get<std::string>();
    if (start != "rest" && start != "equilibrium") throw std::invalid_argument("unknown start '" + start + "'");
    d.start = start == "rest" ? task::SweepStart::Rest : task::SweepStart::Equilibrium;
    d.duration = j.at("duration_s").get<double>();
    d.timeStep = j.at("dt_s").get<double>();
    d.integrator = j.at("integrator").get<std::string>();
    d.tolerance = j.at("tol").get<double>();
    const json& a = j.at("analysis");
    d.analysis = {a.at("min_rate_rad_per_s").get<double>(), a.at("relative_band").get<double>(),
                  a.at("absolute_band_rad_per_s").get<double>(), a.at("min_steady_fraction").get<double>(),
                  a.at("max_relative_spread").get<double>()};
    for (const json& a : j.at("axes")) {
      const auto param = task::findSweepParam(a.at("param").get<std::string>());
      if (!param) throw std::invalid_argument("unknown parameter '" + a.at("param").get<std::string>() + "'");
      d.axes.push_back({*param, a.at("values").get<std::vector<double>>(), a.at("log").get<bool>()});
      if (d.axes.back().values.empty()) throw std::invalid_argument("an axis without values");
    }
    if (d.axes.empty()) throw std::invalid_argument("no axes");
  } catch (const std::exception& e) {  // json's parse, type and missing-key errors, and the checks above
    throw SweepError(SweepError::Kind::BadInput, where + ": not a sweep spec (" + e.what() + ")");
  }
  return d;
}

}  // namespace hemiroll::game
