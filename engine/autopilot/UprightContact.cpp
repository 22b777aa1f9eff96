#include "engine/autopilot/UprightContact.h"

#include <cmath>

#include "engine/physics/ForceDrivenSystem.h"

namespace hemiroll::autopilot {

physics::Vec3 faceNormal(const physics::ModelConstants& constants, const physics::ForceDrivenState& x) {
  const physics::RollingGeometry g = physics::geometryOf(constants, x);
  const physics::Real3 k = g.frame.toBase(g.frame.k);
  return {k.x, k.y, k.z};
}

UprightContact uprightContact(const physics::ModelConstants& constants, const physics::ForceDrivenState& x) {
  using namespace physics::force_slot;
  const physics::Vec3 k = faceNormal(constants, x);
  const double horizontal = std::hypot(k.x(), k.y());
  UprightContact out;
  out.tilt = std::atan2(horizontal, k.z());
  out.point = physics::Vec2(x[u_a], x[v_a]);
  // theta / sin(theta) -> 1 as the tilt vanishes: no division by zero upright.
  const double scale = horizontal > 1e-9 ? out.tilt / horizontal : 1.0;
  out.point -= constants.params.radius * scale * physics::Vec2(k.x(), k.y());
  return out;
}

}  // namespace hemiroll::autopilot
