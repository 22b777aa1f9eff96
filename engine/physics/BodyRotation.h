#pragma once
// The orientation of the hemisphere as a unit quaternion, the alternative to
// the contact angles (u_o, v_o, psi) of eq. (6).
//
// Why: the contact angles have a coordinate singularity on the rim. Their
// rates, eqs. (13)-(15), divide by cos v_o, so u_o' and psi' grow without
// bound as the face turns towards vertical, and sin/cos of three angles sit
// at the head of every evaluation. A quaternion has neither: the face axes
// are quadratic in it and its rate, q' = (0, w) q / 2 for w in the base frame,
// is bilinear. The angles are recovered from it for output.
//
// The rotation is computed from q / |q| (the homogeneous form), so the norm of
// q carries no physics: integrators need not keep it at 1, and its drift
// under RK4 (of order (h |w|)^6 per step) only matters for overflow.

#include "engine/physics/Orientation.h"
#include "engine/physics/Real3.h"

namespace hemiroll::physics {

struct Quaternion {
  double w, x, y, z;
};

// The face axes (the columns of R, body -> base) in the base frame. The
// same interface as HeadingFrame (RollingDynamics.h), for the frame-generic
// dynamics, but with no zero entry to exploit.
struct BodyFrame {
  using Number = double;
  Real3 i, j, k;

  Real3 inPlane(const Real2& q) const { return i * q.x + j * q.y; }
  Real2 toFace(const Real3& v) const { return {dot(i, v), dot(j, v)}; }
};

inline BodyFrame makeBodyFrame(const Quaternion& q) {
  const double s = 2.0 / (q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  const double xx = s * q.x * q.x, yy = s * q.y * q.y, zz = s * q.z * q.z;
  const double xy = s * q.x * q.y, xz = s * q.x * q.z, yz = s * q.y * q.z;
  const double wx = s * q.w * q.x, wy = s * q.w * q.y, wz = s * q.w * q.z;
  return BodyFrame{{1.0 - (yy + zz), xy + wz, xz - wy},
                   {xy - wz, 1.0 - (xx + zz), yz + wx},
                   {xz + wy, yz - wx, 1.0 - (xx + yy)}};
}

// q' = (0, w) q / 2, w the angular velocity in the base frame.
inline Quaternion quaternionRate(const Quaternion& q, const Real3& w) {
  return {-0.5 * (w.x * q.x + w.y * q.y + w.z * q.z), 0.5 * (w.x * q.w + w.y * q.z - w.z * q.y),
          0.5 * (w.y * q.w + w.z * q.x - w.x * q.z), 0.5 * (w.z * q.w + w.x * q.y - w.y * q.x)};
}

// psi along a run of quaternions, continuous (never wrapped) as the CSV
// contract wants, without an atan2 per step. psi = atan2(j_x, j_y) for the
// face's j axis (eq. 6), so psi jumps by 2 pi exactly where the projection of
// j crosses the negative j_y half-axis; follow() counts those crossings from
// the signs alone. Call it at least every step (a step turns j by far less
// than a half turn); psi() gives the continuous value on demand. Undefined
// only where psi itself is: the face vertical along j (v_o = +-pi/2, the rim).
class HeadingTracker {
 public:
  HeadingTracker(const Quaternion& q0, double psi0);
  void follow(const Quaternion& q);
  double psi(const Quaternion& q) const;

 private:
  double jx_ = 0.0, jy_ = 1.0;  // j's projection, up to a positive factor
  long long turns_ = 0;         // whole turns added to atan2
};

// The unit quaternion of R(u_o, v_o, psi), eq. (6).
Quaternion quaternionFromContactAngles(double u_o, double v_o, double psi);
// The contact angles of q on the lower hemisphere; psi on the branch nearest
// psiNear (so that a run keeps it continuous).
ContactAngles contactAnglesFromQuaternion(const Quaternion& q, double psiNear);

}  // namespace hemiroll::physics
