#pragma once
// The double-pendulum actuation of Sec. 5, eqs. (49)-(50):
//   x_p = r1 cos(phi) + r2 cos(k phi),  y_p = r1 sin(phi) - r2 sin(k phi),
// phi = Omega t. For integer k the curve closes with k + 1 leaves.

#include "engine/physics/PrescribedDriveSystem.h"

namespace hemiroll::physics {

struct RoseDef {
  double r1 = 0.015;                       // first link [m]
  double r2 = 0.008;                       // second link [m]
  double k = 8.0;                          // speed ratio of the links [-]
  double omega = -0.31415926535897931;     // Omega, rate of the first link [rad/s] (-pi/10)
};

class RoseDrive final : public MassPointTrajectory {
 public:
  explicit RoseDrive(const RoseDef& def) : def_(def) {}
  Sample at(double t) const override;
  const RoseDef& def() const { return def_; }

 private:
  RoseDef def_;
};

}  // namespace hemiroll::physics
