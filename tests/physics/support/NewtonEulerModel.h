#pragma once
// An independent formulation of the rolling system, for cross-checking the
// engine's minimal (Schur-complement) form.
//
// Two free bodies in the base frame:
//   hemisphere: centre of mass r_s, velocity v_s, orientation q (unit
//               quaternion, body -> base), angular velocity w (base frame),
//               inertia about its centre of mass;
//   mass point: position r_p, velocity v_p (a free particle in 3D).
// Constraint forces are unknowns solved together with the accelerations in
// one dense 13x13 system (Newton-Euler plus acceleration-level constraints):
//   lambda_c (3): force of the plane on the hemisphere at the contact point,
//   lambda_n (1): force of the face on the mass point along k_o (its reaction
//                 -lambda_n k_o acts on the hemisphere at r_p).
// Nothing here uses the engine's dynamics; only its state layout is shared so
// that states can be converted both ways.

#include <functional>

#include "tests/physics/support/TestModel.h"

namespace hemiroll::test {

struct NewtonEulerState {
  Vec3 comPosition;           // r_s [m]
  Vec3 comVelocity;           // v_s [m/s]
  Eigen::Quaterniond attitude;  // body -> base
  Vec3 omega;                 // w, base frame [rad/s]
  Vec3 pointPosition;         // r_p [m]
  Vec3 pointVelocity;         // v_p [m/s]
};

// 19 numbers: r_s, v_s, q (w, x, y, z), w, r_p, v_p; what the integrator sees.
using NewtonEulerVector = Eigen::Matrix<double, 19, 1>;

struct NewtonEulerAccelerations {
  Vec3 comAcceleration;    // a_s [m/s^2]
  Vec3 omegaDot;           // alpha [rad/s^2]
  Vec3 pointAcceleration;  // a_p [m/s^2]
  Vec3 contactForce;       // lambda_c [N]
  double faceNormalForce;  // lambda_n [N]
};

// The force on the mass point (base frame) that the drive applies at (t, state).
using PointForceLaw = std::function<Vec3(double t, const NewtonEulerState&)>;

class NewtonEulerModel {
 public:
  explicit NewtonEulerModel(const HemisphereParams& params);

  // The geometry each evaluation needs.
  Mat3 rotation(const NewtonEulerState& s) const;
  Vec3 faceCentre(const NewtonEulerState& s) const;    // r_o = sphere centre
  Vec3 contactPoint(const NewtonEulerState& s) const;  // r_c = r_o - R e_z, on the plane
  // Velocity of the material point of the hemisphere at the contact (zero when rolling).
  Vec3 contactMaterialVelocity(const NewtonEulerState& s) const;
  Vec3 faceCentreVelocity(const NewtonEulerState& s) const;
  // Inertia about the centre of mass, base frame.
  Mat3 comInertia(const Mat3& rotation) const;

  NewtonEulerAccelerations accelerations(const NewtonEulerState& s, const Vec3& pointForce) const;
  NewtonEulerVector derivative(double t, const NewtonEulerVector& y, const PointForceLaw& force) const;

  // T + V with V = g (m_s z_s + m_p z_p).
  double energy(const NewtonEulerState& s) const;

  // Conversions to and from the engine's 12-state vector (slots of eq. 22).
  NewtonEulerState fromEngine(const State12& x) const;
  State12 toEngine(const NewtonEulerState& s, double psiNear) const;
  // p'' in face coordinates implied by the accelerations.
  Vec2 faceAcceleration(const NewtonEulerState& s, const NewtonEulerAccelerations& a) const;

  static NewtonEulerVector pack(const NewtonEulerState& s);
  static NewtonEulerState unpack(const NewtonEulerVector& y);

  const HemisphereParams& params() const { return p_; }

 private:
  HemisphereParams p_;
  double comDepth_;  // 3R/8
};

// Drives, written from Sec. 3.2 without the engine's coupling code.
PointForceLaw freeMotion();
PointForceLaw constantFaceForce(const Vec2& f);  // f in face coordinates (R N f)
enum class CouplingKind { M1, M2, M3 };
struct ProxyMotion {
  std::function<Vec3(double)> position, velocity;
};
PointForceLaw springCoupling(const NewtonEulerModel& model, CouplingKind kind, double stiffness, double damping,
                             double alpha, const ProxyMotion& proxy);

}  // namespace hemiroll::test
