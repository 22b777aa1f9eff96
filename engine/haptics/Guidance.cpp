#include "engine/haptics/Guidance.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::haptics {

const char* guidanceKindName(GuidanceKind kind) {
  switch (kind) {
    case GuidanceKind::None: return "none";
    case GuidanceKind::Autopilot: return "autopilot";
    case GuidanceKind::ErrorAugmentation: return "error_augmentation";
  }
  return "none";
}

bool parseGuidanceKind(const std::string& name, GuidanceKind& kind) {
  for (const GuidanceKind k : {GuidanceKind::None, GuidanceKind::Autopilot, GuidanceKind::ErrorAugmentation})
    if (name == guidanceKindName(k)) {
      kind = k;
      return true;
    }
  return false;
}

std::string validateGuidance(const GuidanceDef& def) {
  const auto nonNegative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!nonNegative(def.stiffness)) return "stiffness: must be a finite number >= 0 [N/m]";
  if (!nonNegative(def.damping)) return "damping: must be a finite number >= 0 [N s/m]";
  if (!(def.scale >= 0.0 && def.scale <= 1.0)) return "scale: must be in [0, 1]";
  if (!(def.maxError > 0.0) || !std::isfinite(def.maxError)) return "max_error: must be a positive number [m]";
  return {};
}

Vec3 guidanceForce(const GuidanceDef& def, const GuideSample& plan, double t, const Vec3& proxyPosition,
                   const Vec3& proxyVelocity) {
  if (!def.active() || !plan.valid) return Vec3::Zero();
  const double age = t - plan.time;
  if (!(age <= kGuideStaleAfter)) return Vec3::Zero();  // also catches a NaN time
  const double ahead = std::clamp(age, 0.0, kGuideMaxExtrapolation);
  const Vec3 planPosition(plan.position[0], plan.position[1], plan.position[2]);
  const Vec3 planVelocity(plan.velocity[0], plan.velocity[1], plan.velocity[2]);
  const Vec3 target = planPosition + ahead * planVelocity;
  Vec3 error = target - proxyPosition;
  const double length = error.norm();
  if (length > def.maxError) error *= def.maxError / length;
  const double spring = def.kind == GuidanceKind::ErrorAugmentation ? -def.stiffness : def.stiffness;
  const Vec3 force = def.scale * (spring * error + def.damping * (planVelocity - proxyVelocity));
  return force.allFinite() ? force : Vec3::Zero();
}

}  // namespace hemiroll::haptics
