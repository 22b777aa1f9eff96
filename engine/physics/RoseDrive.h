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

// p, p' and p'' at time t, over doubles or lanes (one rose per lane,
// BatchedRk4.h): RoseDrive::at and the batched integrator both use it.
template <class T>
struct RoseSampleOf {
  Real2Of<T> p, pDot, pDDot;  // [m], [m/s], [m/s^2], face coordinates
};
template <class T>
inline RoseSampleOf<T> roseSampleOf(T r1, T r2, T k, T W, double t) {
  const T phi = W * t;
  SinCosOf<T> first, second;
  if constexpr (std::is_same_v<T, double>) {
    sinCos2(phi, k * phi, first, second);  // the engine's trig: same bits on every libm
  } else {
    first = sinCosLanes(phi);
    second = sinCosLanes(k * phi);
  }
  const T c1 = first.cos, s1 = first.sin, ck = second.cos, sk = second.sin;
  return {{r1 * c1 + r2 * ck, r1 * s1 - r2 * sk},
          {W * (-r1 * s1 - k * r2 * sk), W * (r1 * c1 - k * r2 * ck)},
          {(W * W) * (-r1 * c1 - k * k * r2 * ck), (W * W) * (-r1 * s1 + k * k * r2 * sk)}};
}

class RoseDrive final : public MassPointTrajectory {
 public:
  explicit RoseDrive(const RoseDef& def) : def_(def) {}
  Sample at(double t) const override;
  const RoseDef& def() const { return def_; }

 private:
  RoseDef def_;
};

}  // namespace hemiroll::physics
