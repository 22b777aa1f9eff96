#include "game/app/Settings.h"

namespace hemiroll::game {

physics::CouplingDef couplingFor(const Settings& s, const physics::CouplingDef& level) {
  if (!s.overrideCoupling) return level;
  physics::CouplingDef c = level;
  c.method = s.method == 0 ? physics::ForceMethod::M1 : s.method == 1 ? physics::ForceMethod::M2 : physics::ForceMethod::M3;
  c.visualOnly = s.method == 3;
  c.stiffness = s.stiffness;
  c.damping = s.damping;
  c.alpha = s.alpha;
  return c;
}

const char* methodLabel(int method) {
  static constexpr const char* kLabels[] = {"M1", "M2", "M3", "visual"};
  return method >= 0 && method < 4 ? kLabels[method] : "?";
}

}  // namespace hemiroll::game
