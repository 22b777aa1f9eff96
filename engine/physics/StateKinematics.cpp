#include "engine/physics/StateKinematics.h"

#include "engine/physics/Orientation.h"

namespace hemiroll::physics {

Vec3 massPointPosition(const ForceDrivenState& x, double radius) {
  namespace slot = force_slot;
  const Orientation o = makeOrientation(x[slot::u_o], x[slot::v_o], x[slot::psi]);
  const Vec3 centre(x[slot::u_a], x[slot::v_a], radius);
  return centre + o.R * Vec3(x[slot::x_p], x[slot::y_p], 0.0);
}

}  // namespace hemiroll::physics
