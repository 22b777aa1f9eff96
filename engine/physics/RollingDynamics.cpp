#include "engine/physics/RollingDynamics.h"

namespace hemiroll::physics {

namespace {

// Solves S x = r for a symmetric positive definite 3x3 S by its adjugate: S is
// never singular while m_s > 0 (Sec. 3.1), and this is cheaper than a
// factorisation at this size.
Vec3 solveSymmetric3(const Mat3& S, const Vec3& r) {
  const double c00 = S(1, 1) * S(2, 2) - S(1, 2) * S(1, 2);
  const double c01 = S(0, 2) * S(1, 2) - S(0, 1) * S(2, 2);
  const double c02 = S(0, 1) * S(1, 2) - S(0, 2) * S(1, 1);
  const double c11 = S(0, 0) * S(2, 2) - S(0, 2) * S(0, 2);
  const double c12 = S(0, 1) * S(0, 2) - S(0, 0) * S(1, 2);
  const double c22 = S(0, 0) * S(1, 1) - S(0, 1) * S(0, 1);
  const double invDet = 1.0 / (S(0, 0) * c00 + S(0, 1) * c01 + S(0, 2) * c02);
  return Vec3(c00 * r.x() + c01 * r.y() + c02 * r.z(), c01 * r.x() + c11 * r.y() + c12 * r.z(),
              c02 * r.x() + c12 * r.y() + c22 * r.z()) *
         invDet;
}

}  // namespace

RollingGeometry makeGeometry(const ModelConstants& c, const Orientation& o, const Vec2& p, const Vec2& pDot) {
  RollingGeometry g;
  g.orientation = o;
  g.faceNormal = o.R.col(2);
  g.rhoP = g.inPlane(p);
  g.rhoPDot = g.inPlane(pDot);
  g.lever = g.rhoP;
  g.lever.z() += c.params.radius;  // rho_c = -R e_z
  return g;
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

BodyAcceleration RollingDynamics::bodyAcceleration(const RollingGeometry& g, const Vec3& w,
                                                   double externalNormalForce) const {
  const double ms = c_.params.shellMass;
  const double mp = c_.params.pointMass;
  const double R = c_.params.radius;
  const double grav = c_.params.gravity;
  const Vec3& k = g.faceNormal;

  BodyAcceleration a;
  a.pointBias = w.cross(w.cross(g.rhoP)) + 2.0 * w.cross(g.rhoPDot);
  a.pointBias.z() += grav;

  // tau_0 = rho_c x (w x (w x m_s rho_s)) + m_s rho_s x g, rho_s = -(3R/8) k.
  const Vec3 rhoS = -c_.comDepth * k;
  const Vec3 centripetal = ms * w.cross(w.cross(rhoS));
  Vec3 tau(R * centripetal.y(), -R * centripetal.x(), 0.0);  // (-R e_z) x v
  tau.x() += ms * grav * c_.comDepth * k.y();
  tau.y() -= ms * grav * c_.comDepth * k.x();

  const Vec3 n = g.lever.cross(k);
  Mat3 S = contactInertia(k);
  S.noalias() += (mp * n) * n.transpose();
  tau += n * (externalNormalForce - mp * k.dot(a.pointBias));
  a.omegaDot = solveSymmetric3(S, tau);
  return a;
}

Vec2 RollingDynamics::pointAcceleration(const RollingGeometry& g, const BodyAcceleration& a,
                                        const Vec2& f) const {
  return f / c_.params.pointMass + g.toFace(g.lever.cross(a.omegaDot) - a.pointBias);
}

Vec2 RollingDynamics::prescribedForce(const RollingGeometry& g, const BodyAcceleration& a,
                                      const Vec2& pDDot) const {
  return c_.params.pointMass * (pDDot - g.toFace(g.lever.cross(a.omegaDot) - a.pointBias));
}

}  // namespace hemiroll::physics
