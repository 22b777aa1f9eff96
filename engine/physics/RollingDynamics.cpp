#include "engine/physics/RollingDynamics.h"

namespace hemiroll::physics {

MassConstantsOf<double> massConstantsOf(const ModelConstants& c) {
  return {c.params.pointMass, c.params.shellMass, c.params.radius, c.params.gravity, c.comDepth, c.shellMoment};
}

Mat3 RollingDynamics::contactInertia(const Vec3& k) const {
  // J_c = J_o + m_s (hat(rho_s) hat(rho_c) + hat(rho_c) hat(rho_s) - hat(rho_c)^2)
  // with rho_s = -(3R/8) k, rho_c = -R e_z, J_o = (2/5) m_s R^2 I, expanded:
  // m_s R^2 { (7/5 - (3/4) k_z) I + (3/8)(e_z k^T + k e_z^T) - e_z e_z^T }.
  const double m = c_.shellMoment;
  Mat3 J = Mat3::Identity() * (m * (1.4 - 0.75 * k.z()));
  const Vec3 cross = k * (0.375 * m);
  J.row(2) += cross.transpose();
  J.col(2) += cross;
  J(2, 2) -= m;
  return J;
}

}  // namespace hemiroll::physics
