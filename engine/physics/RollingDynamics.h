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
// tests/physics check all of this against the plain 5x5 solve of (23)-(29)
// and against an independent Newton-Euler model.
//
// Why a heading frame: gravity and the contact offset rho_c are vertical, so
// the dynamics look the same in the base frame turned about z by psi. There
// the orientation is R' = Rx(v_o)^T Ry(u_o)^T, which needs no products with
// psi; only w goes in and w' comes out through a 2D rotation.
//
// This is the hot path of every mode (four evaluations per RK4 step), so it
// is inline, on plain doubles (Real3.h says why), and allocation-free. The
// functions are templates over the number type: the batched integrator
// (BatchedRk4.h) runs them on lanes of doubles, with the scalar path's bits.

#include "engine/physics/HemisphereParams.h"
#include "engine/physics/Orientation.h"
#include "engine/physics/Real3.h"
#include "engine/physics/SinCos.h"

namespace hemiroll::physics {

// The base frame turned about the vertical by psi: v_heading = Rz(psi) v_base.
template <class T>
struct HeadingFrameOf {
  using Number = T;
  T cpsi, spsi, cv, sv;
  Real3Of<T> i, j, k;  // face axes: the columns of R' = Rx(v_o)^T Ry(u_o)^T

  Real3Of<T> toHeading(const Real3Of<T>& v) const {
    return {cpsi * v.x - spsi * v.y, spsi * v.x + cpsi * v.y, v.z};
  }
  Real3Of<T> toBase(const Real3Of<T>& v) const { return {cpsi * v.x + spsi * v.y, cpsi * v.y - spsi * v.x, v.z}; }
  Real3Of<T> inPlane(const Real2Of<T>& q) const {
    return {i.x * q.x, i.y * q.x + j.y * q.y, i.z * q.x + j.z * q.y};
  }
  Real2Of<T> toFace(const Real3Of<T>& v) const { return {dot(i, v), j.y * v.y + j.z * v.z}; }  // j.x = 0
};
using HeadingFrame = HeadingFrameOf<double>;

// From sin and cos of u_o, v_o and psi.
template <class T>
inline HeadingFrameOf<T> headingFrameOf(const SinCosOf<T>& u, const SinCosOf<T>& v, const SinCosOf<T>& p) {
  return HeadingFrameOf<T>{p.cos,
                           p.sin,
                           v.cos,
                           v.sin,
                           {u.cos, v.sin * u.sin, v.cos * u.sin},
                           {broadcast<T>(0.0), v.cos, -v.sin},
                           {-u.sin, v.sin * u.cos, v.cos * u.cos}};
}

// The frame at (u_o, v_o, psi): doubles, or one trajectory per lane.
template <class T>
inline HeadingFrameOf<T> makeHeadingFrame(T u_o, T v_o, T psi) {
  if constexpr (std::is_same_v<T, double>) {
    SinCos u, v;
    sinCos2(u_o, v_o, u, v);
    return headingFrameOf(u, v, sinCos(psi));
  } else {
    return headingFrameOf(sinCosLanes(u_o), sinCosLanes(v_o), sinCosLanes(psi));
  }
}

// Everything that depends on the configuration (orientation, p) and the
// mass point's velocity relative to the body, in a frame that shares the
// vertical with the base frame: the heading frame of the 12-state model
// (HeadingFrame), or the base frame itself when the orientation is a
// quaternion (BodyFrame in BodyRotation.h). A Frame gives the face axes
// i, j, k and inPlane()/toFace() between face coordinates and the frame.
template <class Frame>
struct RollingGeometryIn {
  using Number = typename Frame::Number;
  Frame frame;
  Real3Of<Number> rhoP;     // rho_p = R N p, mass point from the face centre
  Real3Of<Number> rhoPDot;  // R N p', its velocity relative to the body
  Real3Of<Number> lever;    // d = rho_p - rho_c, from the contact point to the mass point
};
using RollingGeometry = RollingGeometryIn<HeadingFrame>;

template <class Frame, class T = typename Frame::Number>
inline RollingGeometryIn<Frame> geometryIn(T radius, const Frame& frame, const Real2Of<T>& p, const Real2Of<T>& pDot) {
  const Real3Of<T> rho = frame.inPlane(p);
  return RollingGeometryIn<Frame>{frame, rho, frame.inPlane(pDot), {rho.x, rho.y, rho.z + radius}};
}

template <class Frame>
inline RollingGeometryIn<Frame> makeGeometry(const ModelConstants& c, const Frame& frame, const Real2& p,
                                             const Real2& pDot) {
  return geometryIn(c.params.radius, frame, p, pDot);
}

// The constants one evaluation reads, per trajectory: plain doubles, or one
// lane per trajectory in the batched integrator.
template <class T>
struct MassConstantsOf {
  T pointMass;    // m_p [kg]
  T shellMass;    // m_s [kg]
  T radius;       // R [m]
  T gravity;      // [m/s^2]
  T comDepth;     // 3R/8 [m]
  T shellMoment;  // m_s R^2 [kg m^2]
};
MassConstantsOf<double> massConstantsOf(const ModelConstants& c);

// What one evaluation passes from the 3x3 solve to the mass point (heading frame).
template <class T>
struct BodyAccelerationOf {
  Real3Of<T> omegaDot;   // w' [rad/s^2]
  Real3Of<T> pointBias;  // b = w x (w x rho_p) + 2 w x rho_p' - g [m/s^2]
};
using BodyAcceleration = BodyAccelerationOf<double>;

namespace detail {
// Solves S x = r for a symmetric positive definite 3x3 S by its adjugate: S
// is never singular while m_s > 0 (Sec. 3.1), and this is cheaper than a
// factorisation at this size.
template <class T>
inline Real3Of<T> solveSymmetric3(T s00, T s01, T s02, T s11, T s12, T s22, const Real3Of<T>& r) {
  const T c00 = s11 * s22 - s12 * s12, c01 = s02 * s12 - s01 * s22, c02 = s01 * s12 - s02 * s11;
  const T c11 = s00 * s22 - s02 * s02, c12 = s01 * s02 - s00 * s12, c22 = s00 * s11 - s01 * s01;
  const T invDet = 1.0 / (s00 * c00 + s01 * c01 + s02 * c02);
  return Real3Of<T>{c00 * r.x + c01 * r.y + c02 * r.z, c01 * r.x + c11 * r.y + c12 * r.z,
                    c02 * r.x + c12 * r.y + c22 * r.z} *
         invDet;
}
}  // namespace detail

// w' for angular velocity w (both in the geometry's frame) when an external
// force pushes the mass point with component externalNormalForce = k.F along
// the face normal (zero for M1 and for the prescribed drive; M2 and M3 pass
// theirs through the face).
template <class Frame, class T = typename Frame::Number>
inline BodyAccelerationOf<T> bodyAccelerationOf(const MassConstantsOf<T>& c, const RollingGeometryIn<Frame>& g,
                                                const Real3Of<T>& w, T externalNormalForce) {
  const T mp = c.pointMass, R = c.radius, grav = c.gravity;
  const Real3Of<T>& k = g.frame.k;
  BodyAccelerationOf<T> a;
  a.pointBias = doubleCross(w, g.rhoP) + 2.0 * cross(w, g.rhoPDot);
  a.pointBias.z += grav;

  // tau_0 with rho_s = -(3R/8) k, rho_c = -R e_z, g = -grav e_z; (-R e_z) x v = R (v_y, -v_x, 0).
  const T shellLever = c.shellMass * c.comDepth;                 // m_s 3R/8
  const Real3Of<T> spin = -shellLever * doubleCross(w, k);      // w x (w x m_s rho_s)
  const Real3Of<T> n = cross(g.lever, k);
  const T load = externalNormalForce - mp * dot(k, a.pointBias);
  const Real3Of<T> tau{R * spin.y + shellLever * grav * k.y + n.x * load,
                       -R * spin.x - shellLever * grav * k.x + n.y * load, n.z * load};

  // S = J_c + m_p n n^T, J_c written out as in RollingDynamics::contactInertia.
  const T m = c.shellMoment, diag = m * (1.4 - 0.75 * k.z);
  const Real3Of<T> mpn = mp * n;
  a.omegaDot = detail::solveSymmetric3(diag + mpn.x * n.x, mpn.x * n.y, 0.375 * m * k.x + mpn.x * n.z,
                                       diag + mpn.y * n.y, 0.375 * m * k.y + mpn.y * n.z, 0.4 * m + mpn.z * n.z,
                                       tau);
  return a;
}

// p'' of the force-driven model for in-face force f, eqs. (30), (34), (36).
template <class Frame, class T = typename Frame::Number>
inline Real2Of<T> pointAccelerationOf(const MassConstantsOf<T>& c, const RollingGeometryIn<Frame>& g,
                                      const BodyAccelerationOf<T>& a, const Real2Of<T>& f) {
  const Real2Of<T> q = g.frame.toFace(cross(g.lever, a.omegaDot) - a.pointBias);
  const T invMass = 1.0 / c.pointMass;
  return {f.x * invMass + q.x, f.y * invMass + q.y};
}

class RollingDynamics {
 public:
  explicit RollingDynamics(const HemisphereParams& params) : c_(params), mass_(massConstantsOf(c_)) {}

  const ModelConstants& constants() const { return c_; }
  const MassConstantsOf<double>& massConstants() const { return mass_; }

  // J_c, the inertia of the hemisphere about the contact point. Valid in any
  // frame that shares the vertical with the base frame (base or heading).
  Mat3 contactInertia(const Vec3& faceNormal) const;

  template <class Frame>
  BodyAcceleration bodyAcceleration(const RollingGeometryIn<Frame>& g, const Real3& w,
                                    double externalNormalForce) const {
    return bodyAccelerationOf(mass_, g, w, externalNormalForce);
  }

  template <class Frame>
  Real2 pointAcceleration(const RollingGeometryIn<Frame>& g, const BodyAcceleration& a, const Real2& f) const {
    return pointAccelerationOf(mass_, g, a, f);
  }

  // f that realises a prescribed p'' (eq. 46), for the 8-state drive.
  template <class Frame>
  Real2 prescribedForce(const RollingGeometryIn<Frame>& g, const BodyAcceleration& a, const Real2& pDDot) const {
    const Real2 q = g.frame.toFace(cross(g.lever, a.omegaDot) - a.pointBias);
    const double mp = c_.params.pointMass;
    return {mp * (pDDot.x - q.x), mp * (pDDot.y - q.y)};
  }

 private:
  ModelConstants c_;
  MassConstantsOf<double> mass_;
};

}  // namespace hemiroll::physics
