#include "engine/physics/BodyRotation.h"

#include <Eigen/Geometry>
#include <cmath>

namespace hemiroll::physics {

namespace {
constexpr double kTurn = 6.283185307179586;

// j_x and j_y of makeBodyFrame(q) times |q|^2 / 2: the signs without a division.
void projectedJ(const Quaternion& q, double& jx, double& jy) {
  jx = q.x * q.y - q.w * q.z;
  jy = 0.5 * ((q.w * q.w + q.y * q.y) - (q.x * q.x + q.z * q.z));
}
}  // namespace

HeadingTracker::HeadingTracker(const Quaternion& q0, double psi0) {
  projectedJ(q0, jx_, jy_);
  turns_ = std::llround((psi0 - std::atan2(jx_, jy_)) / kTurn);
}

void HeadingTracker::follow(const Quaternion& q) {
  double jx, jy;
  projectedJ(q, jx, jy);
  if (jy < 0.0 && jy_ < 0.0 && std::signbit(jx) != std::signbit(jx_)) turns_ += std::signbit(jx) ? 1 : -1;
  jx_ = jx;
  jy_ = jy;
}

double HeadingTracker::psi(const Quaternion& q) const {
  double jx, jy;
  projectedJ(q, jx, jy);
  return std::atan2(jx, jy) + kTurn * static_cast<double>(turns_);
}

Quaternion quaternionFromContactAngles(double u_o, double v_o, double psi) {
  const Eigen::Quaterniond q(makeOrientation(u_o, v_o, psi).R);
  return {q.w(), q.x(), q.y(), q.z()};
}

ContactAngles contactAnglesFromQuaternion(const Quaternion& q, double psiNear) {
  const BodyFrame f = makeBodyFrame(q);
  Mat3 R;
  R << f.i.x, f.j.x, f.k.x, f.i.y, f.j.y, f.k.y, f.i.z, f.j.z, f.k.z;
  return contactAnglesFromMatrix(R, psiNear);
}

}  // namespace hemiroll::physics
