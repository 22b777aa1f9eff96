#include "engine/task/SweepDef.h"

namespace hemiroll::task {

const std::array<SweepParamInfo, 8>& sweepParams() {
  static const std::array<SweepParamInfo, 8> kParams = {{
      {SweepParam::R, "R", "R_m", "R [m]"},
      {SweepParam::m_s, "m_s", "m_s_kg", "m_s [kg]"},
      {SweepParam::m_p, "m_p", "m_p_kg", "m_p [kg]"},
      {SweepParam::g, "g", "g_m_per_s2", "g [m/s^2]"},
      {SweepParam::r1, "r1", "r1_m", "r1 [m]"},
      {SweepParam::r2, "r2", "r2_m", "r2 [m]"},
      {SweepParam::k, "k", "k", "k [-]"},
      {SweepParam::Omega, "Omega", "Omega_rad_per_s", "Omega [rad/s]"},
  }};
  return kParams;
}

const SweepParamInfo& sweepParamInfo(SweepParam param) { return sweepParams()[static_cast<std::size_t>(param)]; }

std::optional<SweepParam> findSweepParam(std::string_view name) {
  for (const SweepParamInfo& info : sweepParams())
    if (name == info.name) return info.param;
  return std::nullopt;
}

double sweepParamValue(SweepParam param, const physics::HemisphereParams& params, const physics::RoseDef& rose) {
  switch (param) {
    case SweepParam::R: return params.radius;
    case SweepParam::m_s: return params.shellMass;
    case SweepParam::m_p: return params.pointMass;
    case SweepParam::g: return params.gravity;
    case SweepParam::r1: return rose.r1;
    case SweepParam::r2: return rose.r2;
    case SweepParam::k: return rose.k;
    case SweepParam::Omega: return rose.omega;
  }
  return 0.0;
}

void setSweepParam(SweepParam param, double value, physics::HemisphereParams& params, physics::RoseDef& rose) {
  switch (param) {
    case SweepParam::R: params.radius = value; break;
    case SweepParam::m_s: params.shellMass = value; break;
    case SweepParam::m_p: params.pointMass = value; break;
    case SweepParam::g: params.gravity = value; break;
    case SweepParam::r1: rose.r1 = value; break;
    case SweepParam::r2: rose.r2 = value; break;
    case SweepParam::k: rose.k = value; break;
    case SweepParam::Omega: rose.omega = value; break;
  }
}

const char* sweepStartName(SweepStart start) { return start == SweepStart::Rest ? "rest" : "equilibrium"; }

long long SweepDef::pointCount() const {
  if (axes.empty()) return 0;
  long long count = 1;
  for (const SweepAxis& axis : axes) count *= static_cast<long long>(axis.values.size());
  return count;
}

}  // namespace hemiroll::task
