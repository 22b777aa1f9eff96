#include "engine/physics/Orientation.h"

#include "engine/physics/SinCos.h"

#include <cmath>
#include <numbers>

namespace hemiroll::physics {

Orientation makeOrientation(double u_o, double v_o, double psi) {
  const SinCos u = sinCos(u_o), v = sinCos(v_o), p = sinCos(psi);
  Orientation o;
  o.cu = u.cos;
  o.su = u.sin;
  o.cv = v.cos;
  o.sv = v.sin;
  o.cpsi = p.cos;
  o.spsi = p.sin;
  // Columns are i_o, j_o, k_o; written out from Rz(psi)^T Rx(v)^T Ry(u)^T.
  o.R << o.cu * o.cpsi + o.su * o.sv * o.spsi, o.cv * o.spsi, -o.su * o.cpsi + o.cu * o.sv * o.spsi,
      -o.cu * o.spsi + o.su * o.sv * o.cpsi, o.cv * o.cpsi, o.su * o.spsi + o.cu * o.sv * o.cpsi,
      o.su * o.cv, -o.sv, o.cu * o.cv;
  return o;
}

ContactAngles contactAnglesFromMatrix(const Mat3& R, double psiNear) {
  ContactAngles a;
  a.u_o = std::atan2(R(2, 0), R(2, 2));
  a.v_o = std::atan2(-R(2, 1), std::hypot(R(2, 0), R(2, 2)));
  const double psi = std::atan2(R(0, 1), R(1, 1));
  const double turn = 2.0 * std::numbers::pi;
  a.psi = psi + turn * std::round((psiNear - psi) / turn);
  return a;
}

}  // namespace hemiroll::physics
