#pragma once
// The dynamics of eqs. (20)-(30) in the efficient form the paper asks for
// (Sec. 3.1): only a 3x3 symmetric system is solved per evaluation.
//
// Why this is the paper's Schur complement: with A = hat(d), d = rho_p - rho_c,
// B = R N and k = R e_z, eliminating p'' from (23) gives eqs. (33)-(37) with
// the CORRECTED (37) (physics-notes.md):
//   S = H_ss - H_sp H_pp^-1 H_ps = J_c + m_p (A k)(A k)^T.
// Substituting h_p and h_s of (28)-(29), every in-plane term cancels (the face
// is frictionless, so only the normal load of the mass point reaches the
// hemisphere) and the right-hand side reduces to
//   S w' = tau_0 + n (k.F - m_p k.b),   n = d x k,
//   tau_0 = rho_c x (w x (w x m_s rho_s)) + m_s rho_s x g,
//   b = w x (w x rho_p) + 2 w x rho_p' - g,
// after which (34)/(36) give p'' = B^T F / m_p + B^T (d x w' - b).
// The same S serves the prescribed drive: eq. (47) is S w' = tau_0 - n m_p k.b.
// tests/physics/RollingDynamicsTest.cpp checks all of this against the plain
// 5x5 solve of (23)-(29) and against an independent Newton-Euler model.

#include "engine/physics/HemisphereParams.h"
#include "engine/physics/Orientation.h"

namespace hemiroll::physics {

// Everything that depends on the configuration (u_o, v_o, psi, p) and the
// mass point's relative velocity, in the base frame.
struct RollingGeometry {
  Orientation orientation;
  Vec3 faceNormal;   // k_o
  Vec3 rhoP;         // rho_p = R N p, mass point from the face centre
  Vec3 rhoPDot;      // R N p', its velocity relative to the body
  Vec3 lever;        // d = rho_p - rho_c, from the contact point to the mass point

  Vec3 inPlane(const Vec2& faceVector) const {
    return orientation.R.col(0) * faceVector.x() + orientation.R.col(1) * faceVector.y();
  }
  Vec2 toFace(const Vec3& v) const { return {orientation.R.col(0).dot(v), orientation.R.col(1).dot(v)}; }
};

RollingGeometry makeGeometry(const ModelConstants& c, const Orientation& o, const Vec2& p, const Vec2& pDot);

// Terms of one evaluation that both models need after the 3x3 solve.
struct BodyAcceleration {
  Vec3 omegaDot;   // w' [rad/s^2]
  Vec3 pointBias;  // b = w x (w x rho_p) + 2 w x rho_p' - g [m/s^2]
};

class RollingDynamics {
 public:
  explicit RollingDynamics(const HemisphereParams& params) : c_(params) {}

  const ModelConstants& constants() const { return c_; }

  // J_c, the inertia of the hemisphere about the contact point, base frame.
  Mat3 contactInertia(const Vec3& faceNormal) const;

  // w' for angular velocity w when an external force pushes the mass point
  // with component externalNormalForce = k.F along the face normal (zero for
  // M1 and for the prescribed drive; M2 and M3 pass theirs through the face).
  BodyAcceleration bodyAcceleration(const RollingGeometry& g, const Vec3& omega,
                                    double externalNormalForce) const;

  // p'' of the force-driven model for in-face force f, eqs. (30), (34), (36).
  Vec2 pointAcceleration(const RollingGeometry& g, const BodyAcceleration& a, const Vec2& f) const;

  // f that realises a prescribed p'' (eq. 46), for the 8-state drive.
  Vec2 prescribedForce(const RollingGeometry& g, const BodyAcceleration& a, const Vec2& pDDot) const;

 private:
  ModelConstants c_;
};

}  // namespace hemiroll::physics
