#include "tests/physics/support/NewtonEulerModel.h"

#include <Eigen/LU>
#include <cmath>

namespace hemiroll::test {

namespace {
using Mat13 = Eigen::Matrix<double, 13, 13>;
using Vec13 = Eigen::Matrix<double, 13, 1>;
}  // namespace

NewtonEulerModel::NewtonEulerModel(const HemisphereParams& params)
    : p_(params), comDepth_(3.0 * params.radius / 8.0) {}

Mat3 NewtonEulerModel::rotation(const NewtonEulerState& s) const { return s.attitude.normalized().toRotationMatrix(); }

Vec3 NewtonEulerModel::faceCentre(const NewtonEulerState& s) const {
  return s.comPosition + comDepth_ * rotation(s).col(2);
}

Vec3 NewtonEulerModel::contactPoint(const NewtonEulerState& s) const {
  return faceCentre(s) - p_.radius * Vec3::UnitZ();
}

Vec3 NewtonEulerModel::contactMaterialVelocity(const NewtonEulerState& s) const {
  return s.comVelocity + s.omega.cross(contactPoint(s) - s.comPosition);
}

Vec3 NewtonEulerModel::faceCentreVelocity(const NewtonEulerState& s) const {
  return s.comVelocity + s.omega.cross(faceCentre(s) - s.comPosition);
}

Mat3 NewtonEulerModel::comInertia(const Mat3& rot) const {
  // About the face centre the homogeneous hemisphere has (2/5) m_s R^2 I. The
  // parallel-axis theorem moves it to the centre of mass, 3R/8 down the axis:
  // axial (2/5) m_s R^2, transverse (2/5 - 9/64) m_s R^2 = (83/320) m_s R^2.
  const double mR2 = p_.shellMass * p_.radius * p_.radius;
  const Eigen::Vector3d body(83.0 / 320.0 * mR2, 83.0 / 320.0 * mR2, 0.4 * mR2);
  return rot * body.asDiagonal() * rot.transpose();
}

NewtonEulerAccelerations NewtonEulerModel::accelerations(const NewtonEulerState& s, const Vec3& F) const {
  const double ms = p_.shellMass, mp = p_.pointMass;
  const Vec3 gravity(0.0, 0.0, -p_.gravity);
  const Mat3 rot = rotation(s);
  const Vec3 k = rot.col(2);
  const Mat3 J = comInertia(rot);
  const Vec3& w = s.omega;
  const Vec3 ro = faceCentre(s);
  const Vec3 rc = ro - p_.radius * Vec3::UnitZ();
  const Vec3 e = ro - s.comPosition;        // centre of mass -> face centre
  const Vec3 c = rc - s.comPosition;        // centre of mass -> contact
  const Vec3 rho = s.pointPosition - ro;    // face centre -> mass point
  const Vec3 vo = s.comVelocity + w.cross(e);

  // Unknowns z = [a_s, alpha, a_p, lambda_c, lambda_n].
  Mat13 A = Mat13::Zero();
  Vec13 b = Vec13::Zero();
  // Hemisphere, translation: m_s a_s = m_s g + lambda_c - lambda_n k.
  A.block<3, 3>(0, 0) = ms * Mat3::Identity();
  A.block<3, 3>(0, 9) = -Mat3::Identity();
  A.block<3, 1>(0, 12) = k;
  b.segment<3>(0) = ms * gravity;
  // Hemisphere, rotation about its centre of mass:
  // J alpha + w x J w = c x lambda_c + (r_p - r_s) x (-lambda_n k).
  A.block<3, 3>(3, 3) = J;
  A.block<3, 3>(3, 9) = -hat(c);
  A.block<3, 1>(3, 12) = (s.pointPosition - s.comPosition).cross(k);
  b.segment<3>(3) = -w.cross(J * w);
  // Mass point: m_p a_p = m_p g + F + lambda_n k.
  A.block<3, 3>(6, 6) = mp * Mat3::Identity();
  A.block<3, 1>(6, 12) = -k;
  b.segment<3>(6) = mp * gravity + F;
  // Rolling: the material point at the contact has zero velocity,
  // v_s + w x (r_c - r_s) = 0 for all t, where r_c slides over the body with
  // r_c' = v_o (the sphere centre's velocity). Differentiating:
  // a_s + alpha x c + w x (v_o - v_s) = a_s + alpha x c + w x (w x e) = 0.
  A.block<3, 3>(9, 0) = Mat3::Identity();
  A.block<3, 3>(9, 3) = -hat(c);
  b.segment<3>(9) = -w.cross(w.cross(e));
  // Face: (r_p - r_o).k = 0. Second derivative, with
  // a_o = a_s + alpha x e + w x (w x e) and k' = w x k:
  // k.(a_p - a_o) + 2 (v_p - v_o).(w x k) + rho.(alpha x k + w x (w x k)) = 0.
  A.block<1, 3>(12, 0) = -k.transpose();
  A.block<1, 3>(12, 3) = (-e.cross(k) + k.cross(rho)).transpose();
  A.block<1, 3>(12, 6) = k.transpose();
  b(12) = k.dot(w.cross(w.cross(e))) - 2.0 * (s.pointVelocity - vo).dot(w.cross(k)) - rho.dot(w.cross(w.cross(k)));

  const Vec13 z = A.fullPivLu().solve(b);
  return {z.segment<3>(0), z.segment<3>(3), z.segment<3>(6), z.segment<3>(9), z(12)};
}

NewtonEulerVector NewtonEulerModel::pack(const NewtonEulerState& s) {
  NewtonEulerVector y;
  y << s.comPosition, s.comVelocity, s.attitude.w(), s.attitude.x(), s.attitude.y(), s.attitude.z(), s.omega,
      s.pointPosition, s.pointVelocity;
  return y;
}

NewtonEulerState NewtonEulerModel::unpack(const NewtonEulerVector& y) {
  NewtonEulerState s;
  s.comPosition = y.segment<3>(0);
  s.comVelocity = y.segment<3>(3);
  s.attitude = Eigen::Quaterniond(y(6), y(7), y(8), y(9));
  s.omega = y.segment<3>(10);
  s.pointPosition = y.segment<3>(13);
  s.pointVelocity = y.segment<3>(16);
  return s;
}

NewtonEulerVector NewtonEulerModel::derivative(double t, const NewtonEulerVector& y, const PointForceLaw& force) const {
  const NewtonEulerState s = unpack(y);
  const NewtonEulerAccelerations a = accelerations(s, force(t, s));
  // q' = (1/2) (0, w) q for w in the base frame and q: body -> base.
  const Eigen::Quaterniond wq(0.0, s.omega.x(), s.omega.y(), s.omega.z());
  const Eigen::Quaterniond qdot = wq * s.attitude;
  NewtonEulerVector d;
  d << s.comVelocity, a.comAcceleration, 0.5 * qdot.w(), 0.5 * qdot.x(), 0.5 * qdot.y(), 0.5 * qdot.z(), a.omegaDot,
      s.pointVelocity, a.pointAcceleration;
  return d;
}

double NewtonEulerModel::energy(const NewtonEulerState& s) const {
  const Mat3 J = comInertia(rotation(s));
  const double kinetic = 0.5 * p_.shellMass * s.comVelocity.squaredNorm() + 0.5 * s.omega.dot(J * s.omega) +
                         0.5 * p_.pointMass * s.pointVelocity.squaredNorm();
  return kinetic + p_.gravity * (p_.shellMass * s.comPosition.z() + p_.pointMass * s.pointPosition.z());
}

NewtonEulerState NewtonEulerModel::fromEngine(const State12& x) const {
  const Mat3 rot = orientationFromAngles(x(9), x(10), x(11));
  const Vec3 w = x.segment<3>(4);
  const Vec3 ro(x(7), x(8), p_.radius);
  const Vec3 rc(x(7), x(8), 0.0);
  const Vec3 rho = rot.col(0) * x(0) + rot.col(1) * x(1);
  const Vec3 rhoRel = rot.col(0) * x(2) + rot.col(1) * x(3);
  NewtonEulerState s;
  s.comPosition = ro - comDepth_ * rot.col(2);
  s.comVelocity = w.cross(s.comPosition - rc);  // rolling: the contact is at rest
  s.attitude = Eigen::Quaterniond(rot);
  s.omega = w;
  s.pointPosition = ro + rho;
  s.pointVelocity = w.cross(ro - rc) + w.cross(rho) + rhoRel;
  return s;
}

State12 NewtonEulerModel::toEngine(const NewtonEulerState& s, double psiNear) const {
  const Mat3 rot = rotation(s);
  // Row 3 of R = Rz^T Rx^T Ry^T is (sin u cos v, -sin v, cos u cos v).
  const double u = std::atan2(rot(2, 0), rot(2, 2));
  const double v = std::atan2(-rot(2, 1), std::hypot(rot(2, 0), rot(2, 2)));
  // R Ry(u) Rx(v) = Rz(psi)^T, whose first row is (cos psi, sin psi, 0).
  const Mat3 Rz = rot * Eigen::AngleAxisd(u, Vec3::UnitY()).toRotationMatrix() *
                  Eigen::AngleAxisd(v, Vec3::UnitX()).toRotationMatrix();
  double psi = std::atan2(Rz(0, 1), Rz(0, 0));
  psi += 2.0 * kPi * std::round((psiNear - psi) / (2.0 * kPi));
  const Vec3 ro = faceCentre(s);
  const Vec3 rho = s.pointPosition - ro;
  const Vec3 rhoRel = s.pointVelocity - faceCentreVelocity(s) - s.omega.cross(rho);
  State12 x;
  x << rot.col(0).dot(rho), rot.col(1).dot(rho), rot.col(0).dot(rhoRel), rot.col(1).dot(rhoRel), s.omega, ro.x(),
      ro.y(), u, v, psi;
  return x;
}

Vec2 NewtonEulerModel::faceAcceleration(const NewtonEulerState& s, const NewtonEulerAccelerations& a) const {
  // r_p - r_o = R N p; twice differentiated:
  // a_p - a_o = R N p'' + 2 w x R N p' + alpha x rho + w x (w x rho).
  const Mat3 rot = rotation(s);
  const Vec3& w = s.omega;
  const Vec3 ro = faceCentre(s);
  const Vec3 e = ro - s.comPosition;
  const Vec3 rho = s.pointPosition - ro;
  const Vec3 rhoRel = s.pointVelocity - faceCentreVelocity(s) - w.cross(rho);
  const Vec3 ao = a.comAcceleration + a.omegaDot.cross(e) + w.cross(w.cross(e));
  const Vec3 rel = a.pointAcceleration - ao - 2.0 * w.cross(rhoRel) - a.omegaDot.cross(rho) - w.cross(w.cross(rho));
  return {rot.col(0).dot(rel), rot.col(1).dot(rel)};
}

PointForceLaw freeMotion() {
  return [](double, const NewtonEulerState&) { return Vec3::Zero().eval(); };
}

PointForceLaw constantFaceForce(const Vec2& f) {
  return [f](double, const NewtonEulerState& s) {
    const Mat3 rot = s.attitude.normalized().toRotationMatrix();
    return (rot.col(0) * f.x() + rot.col(1) * f.y()).eval();
  };
}

PointForceLaw springCoupling(const NewtonEulerModel& model, CouplingKind kind, double stiffness, double damping,
                             double alpha, const ProxyMotion& proxy) {
  return [&model, kind, stiffness, damping, alpha, proxy](double t, const NewtonEulerState& s) {
    const Mat3 rot = model.rotation(s);
    // Eqs. (41), (43)-(45): gains in the body frame, rotated to the base.
    const double normalGain = kind == CouplingKind::M3 ? alpha : 1.0;
    const Mat3 shape = rot * Vec3(1.0, 1.0, normalGain).asDiagonal() * rot.transpose();
    const Vec3 F = -stiffness * shape * (s.pointPosition - proxy.position(t)) -
                   damping * shape * (s.pointVelocity - proxy.velocity(t));
    if (kind != CouplingKind::M1) return F;
    // M1, eq. (42): only N^T R^T F_h reaches the model.
    const Vec3 k = rot.col(2);
    return (F - k * k.dot(F)).eval();
  };
}

}  // namespace hemiroll::test
