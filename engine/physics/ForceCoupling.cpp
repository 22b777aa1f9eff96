#include "engine/physics/ForceCoupling.h"

#include <cmath>

namespace hemiroll::physics {

std::string validateCoupling(const CouplingDef& def) {
  if (!std::isfinite(def.stiffness) || def.stiffness < 0.0) return "kr (stiffness) must be a finite, non-negative N/m";
  if (!std::isfinite(def.damping) || def.damping < 0.0) return "kv (damping) must be a finite, non-negative N s/m";
  if (!std::isfinite(def.alpha) || def.alpha <= 0.0) return "alpha (normal/in-face gain ratio) must be positive";
  return {};
}

PointKinematics pointKinematics(const RollingGeometry& g, double radius, double u_a, double v_a,
                                const Vec3& omega) {
  return PointKinematics{Vec3(u_a, v_a, radius) + g.rhoP, omega.cross(g.lever) + g.rhoPDot};
}

CouplingForces computeCoupling(const CouplingDef& def, const RollingGeometry& g, const PointKinematics& point,
                               const ProxyPose& proxy) {
  const Vec3 dr = point.position - proxy.position;
  const Vec3 dv = point.velocity - proxy.velocity;
  const Vec3& k = g.faceNormal;

  CouplingForces out;
  out.handForce = -def.stiffness * dr - def.damping * dv;
  if (def.method == ForceMethod::M3) {
    // R diag(k, k, alpha k) R^T = k I + (alpha - 1) k k_o k_o^T: only the
    // normal component is stiffer, so no rotation to the body frame is needed.
    const double extra = (def.alpha - 1.0) * (def.stiffness * k.dot(dr) + def.damping * k.dot(dv));
    out.handForce -= extra * k;
  }
  out.modelForce = out.handForce;
  if (def.method == ForceMethod::M1) out.modelForce -= k * k.dot(out.handForce);
  out.deviceForce = def.visualOnly ? Vec3::Zero() : Vec3(-out.handForce);
  return out;
}

const char* forceMethodName(ForceMethod m) {
  switch (m) {
    case ForceMethod::M1: return "M1";
    case ForceMethod::M2: return "M2";
    case ForceMethod::M3: return "M3";
  }
  return "?";
}

}  // namespace hemiroll::physics
