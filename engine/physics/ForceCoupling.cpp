#include "engine/physics/ForceCoupling.h"

#include <cmath>

namespace hemiroll::physics {

std::optional<FieldError> couplingError(const CouplingDef& def) {
  if (!std::isfinite(def.stiffness) || def.stiffness < 0.0)
    return FieldError{"kr", "(stiffness) must be a finite, non-negative N/m"};
  if (def.stiffness > kMaxStiffness) return FieldError{"kr", "(stiffness) must be at most 1e6 N/m"};
  if (!std::isfinite(def.damping) || def.damping < 0.0)
    return FieldError{"kv", "(damping) must be a finite, non-negative N s/m"};
  if (def.damping > kMaxDamping) return FieldError{"kv", "(damping) must be at most 1e4 N s/m"};
  if (!std::isfinite(def.alpha) || def.alpha <= 0.0)
    return FieldError{"alpha", "(normal/in-face gain ratio) must be positive"};
  if (def.alpha > kMaxAlpha) return FieldError{"alpha", "(normal/in-face gain ratio) must be at most 100"};
  return std::nullopt;
}

std::string validateCoupling(const CouplingDef& def) {
  const auto error = couplingError(def);
  return error ? error->sentence() : std::string();
}

PointKinematics pointKinematics(const RollingGeometry& g, double radius, double u_a, double v_a,
                                const Vec3& omega) {
  const HeadingFrame& f = g.frame;
  const Real3 velocity = cross(f.toHeading(Real3::from(omega)), g.lever) + g.rhoPDot;
  const Real3 centre{u_a, v_a, radius};
  return PointKinematics{(centre + f.toBase(g.rhoP)).eigen(), f.toBase(velocity).eigen()};
}

const char* forceMethodName(ForceMethod m) {
  switch (m) {
    case ForceMethod::M1: return "M1";
    case ForceMethod::M2: return "M2";
    case ForceMethod::M3: return "M3";
  }
  return "?";
}

std::optional<ForceMethod> forceMethodFromName(std::string_view name) {
  for (const ForceMethod m : {ForceMethod::M1, ForceMethod::M2, ForceMethod::M3})
    if (name == forceMethodName(m)) return m;
  return std::nullopt;
}

}  // namespace hemiroll::physics
