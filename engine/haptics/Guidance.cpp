#include "engine/haptics/Guidance.h"

#include <cstdio>

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
  if (!nonNegative(def.stiffness) || def.stiffness > physics::kMaxStiffness)
    return "stiffness: must be a number from 0 to 1e6 [N/m]";
  if (!nonNegative(def.damping) || def.damping > physics::kMaxDamping)
    return "damping: must be a number from 0 to 1e4 [N s/m]";
  if (!(def.scale >= 0.0 && def.scale <= 1.0)) return "scale: must be in [0, 1]";
  if (!(def.maxError > 0.0) || !(def.maxError <= physics::kMaxGuidanceError))
    return "max_error: must be a positive number of at most 1 [m]";
  return {};
}

std::string guidanceProblem(const GuidanceDef& def, const DeviceSpec& device) {
  if (std::string problem = validateGuidance(def); !problem.empty()) return problem;
  if (def.active() && device.hasForceOutput && def.stiffness > device.maxStiffness) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "stiffness: %g N/m is more than the %g N/m the %s device renders stably", def.stiffness,
                  device.maxStiffness, device.name);
    return text;
  }
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
