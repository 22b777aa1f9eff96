#pragma once
// Orientation of the hemisphere and the contact kinematics, eqs. (1), (6),
// (11)-(15). The body frame sits at the centre of the flat face, z along the
// face normal; the sphere centre is r_o = (u_a, v_a, R).

#include "engine/physics/Real3.h"

namespace hemiroll::physics {

// Trigonometry of (u_o, v_o, psi) and the matrix R of eq. (6), computed once
// per evaluation and shared by the kinematics, the dynamics and the couplings.
struct Orientation {
  double cu, su, cv, sv, cpsi, spsi;
  Mat3 R;  // body frame -> base frame, R = Rz(psi)^T Rx(v_o)^T Ry(u_o)^T

  Vec3 faceNormal() const { return R.col(2); }  // k_o in the base frame
  double cosTilt() const { return cu * cv; }    // k_o . e_z
};

Orientation makeOrientation(double u_o, double v_o, double psi);

// Contact kinematics, eqs. (11)-(15): rates of (u_a, v_a, u_o, v_o, psi) for
// angular velocity w (base frame). Eq. (31) as printed multiplies u_o' by
// cos v_o; it must divide (physics-notes.md).
template <class T>
struct ContactRatesOf {
  T u_a, v_a, u_o, v_o, psi;
};
using ContactRates = ContactRatesOf<double>;
template <class T>
inline ContactRatesOf<T> contactRates(T cosV, T sinV, T cosPsi, T sinPsi, T radius, const Real3Of<T>& w) {
  const T a = w.x * sinPsi + w.y * cosPsi;
  const T secV = 1.0 / cosV;
  return ContactRatesOf<T>{radius * w.y, -radius * w.x, -a * secV, -w.x * cosPsi + w.y * sinPsi,
                           -w.z - a * sinV * secV};
}
// The hemisphere's eight rates (w', then the contact rates) in the slot order
// of body_slot, which is also slots 4..11 of the 12-state model: both models
// write their tail through this one function.
template <class T>
inline void writeBodyRates(T* out, const Real3Of<T>& omegaDot, const ContactRatesOf<T>& r) {
  out[0] = omegaDot.x;
  out[1] = omegaDot.y;
  out[2] = omegaDot.z;
  out[3] = r.u_a;
  out[4] = r.v_a;
  out[5] = r.u_o;
  out[6] = r.v_o;
  out[7] = r.psi;
}
inline ContactRates contactRates(const Orientation& o, double radius, const Vec3& omega) {
  return contactRates(o.cv, o.sv, o.cpsi, o.spsi, radius, Real3::from(omega));
}

// Inverse of eq. (6) on the lower hemisphere (|u_o|, |v_o| < pi/2). psi is
// returned in (-pi, pi]; pass the previous value to get the continuous branch.
struct ContactAngles {
  double u_o, v_o, psi;
};
ContactAngles contactAnglesFromMatrix(const Mat3& R, double psiNear = 0.0);

}  // namespace hemiroll::physics
