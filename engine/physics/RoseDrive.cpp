#include "engine/physics/RoseDrive.h"

#include "engine/physics/SinCos.h"

namespace hemiroll::physics {

MassPointTrajectory::Sample RoseDrive::at(double t) const {
  const double W = def_.omega, k = def_.k, r1 = def_.r1, r2 = def_.r2;
  const double phi = W * t;
  SinCos first, second;
  sinCos2(phi, k * phi, first, second);  // the engine's trig: same bits on every libm
  const double c1 = first.cos, s1 = first.sin, ck = second.cos, sk = second.sin;
  Sample s;
  s.p = Vec2(r1 * c1 + r2 * ck, r1 * s1 - r2 * sk);
  s.pDot = W * Vec2(-r1 * s1 - k * r2 * sk, r1 * c1 - k * r2 * ck);
  s.pDDot = (W * W) * Vec2(-r1 * c1 - k * k * r2 * ck, -r1 * s1 + k * k * r2 * sk);
  return s;
}

}  // namespace hemiroll::physics
