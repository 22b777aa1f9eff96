#include "engine/script/ProtocolDef.h"

#include <algorithm>

namespace hemiroll::script {

physics::CouplingDef overriddenCoupling(const TrialOverrides& o, const physics::CouplingDef& level) {
  physics::CouplingDef c = level;
  if (o.method) {
    // The loader accepts only these four names.
    c.visualOnly = *o.method == "visual";
    c.method = *o.method == "M1"   ? physics::ForceMethod::M1
               : *o.method == "M2" ? physics::ForceMethod::M2
                                   : physics::ForceMethod::M3;
  }
  c.stiffness = o.stiffness.value_or(c.stiffness);
  c.damping = o.damping.value_or(c.damping);
  c.alpha = o.alpha.value_or(c.alpha);
  return c;
}

void applyTrialOverrides(const TrialOverrides& overrides, LevelDef& level) {
  level.coupling = overriddenCoupling(overrides, level.coupling);
  level.task.timeLimit = overrides.timeLimit.value_or(level.task.timeLimit);
}

bool isFolderName(const std::string& id) {
  if (id.empty() || id.size() > 64) return false;
  for (const char c : id)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_'))
      return false;
  return true;
}

std::string couplingMethodName(const physics::CouplingDef& coupling) {
  return coupling.visualOnly ? "visual" : physics::forceMethodName(coupling.method);
}

}  // namespace hemiroll::script

namespace hemiroll::script {

double GuidanceSpec::fadeAt(int trialInBlock) const {
  if (fade.overTrials <= 1 || trialInBlock >= fade.overTrials) return fade.to;
  const double progress = static_cast<double>(std::max(trialInBlock, 1) - 1) / (fade.overTrials - 1);
  return fade.from + (fade.to - fade.from) * progress;
}

}  // namespace hemiroll::script
