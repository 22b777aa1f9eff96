#pragma once
// Force couplings between the haptic proxy and the mass point, Sec. 3.2.
// F_h is the force on the mass point; the device renders -F_h to the hand.
//   M1: F_h = -k_r (r_p - r_h) - k_v (v_p - v_h); only its in-face part drives
//       the model (eq. 42).
//   M2: the same F_h, all of it: in-face to the mass point, the normal part
//       through the face to the hemisphere.
//   M3: as M2 with anisotropic gains K = R diag(k, k, alpha k) R^T (eqs. 43-45);
//       the damping gets the same anisotropy.
// Visual only (Sec. 4.1): the model is driven exactly as by the chosen method,
// but no force is rendered.

#include <optional>
#include <string>
#include <string_view>

#include "engine/physics/FieldError.h"
#include "engine/physics/RollingDynamics.h"

namespace hemiroll::physics {

enum class ForceMethod { M1, M2, M3 };

struct CouplingDef {
  ForceMethod method = ForceMethod::M3;
  double stiffness = 250.0;  // k_r [N/m] (in-face stiffness for M3)
  double damping = 10.0;     // k_v [N s/m]
  double alpha = 2.0;        // M3 only: k_rz / k_rx (and k_vz / k_vx) [-]
  bool visualOnly = false;   // drive the model, render no force
};

// The largest gains any input may give, wherever it is given (a level's
// force table, a scenario's drive, a protocol's kr/kv/alpha and guidance,
// the command line): far above what a device renders (1000 N/m) or a model
// needs, and small enough that gain times error stays far from overflow (a
// guidance stiffness of 1e300 made forces of 1e297 N).
inline constexpr double kMaxStiffness = 1e6;  // [N/m]
inline constexpr double kMaxDamping = 1e4;    // [N s/m]
inline constexpr double kMaxAlpha = 100.0;    // [-]
// A guidance spring's reach (its max_error) may be at most this [m]: a
// reach beyond the scene is no reach at all.
inline constexpr double kMaxGuidanceError = 1.0;

// Nothing when valid, else the first offending gain ("kr", as a level's
// force table or a scenario's drive writes it) and what is wrong with it.
std::optional<FieldError> couplingError(const CouplingDef& def);
// The same as one sentence naming the field; empty when valid.
std::string validateCoupling(const CouplingDef& def);

// Position and velocity of the haptic proxy in the base frame [m], [m/s].
struct ProxyPose {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
};

struct CouplingForces {
  Vec3 handForce;    // F_h on the mass point [N], base frame
  Vec3 modelForce;   // the part of F_h the model receives [N]
  Vec3 deviceForce;  // force to render on the device [N]: -F_h, or zero if visual only
};

// The gains of one coupling, per trajectory: doubles, or one lane per
// trajectory in the batched integrator (the method is shared).
template <class T>
struct CouplingLawOf {
  ForceMethod method;
  T stiffness, damping, alpha;  // k_r [N/m], k_v [N s/m], M3's anisotropy [-]
};
inline CouplingLawOf<double> couplingLawOf(const CouplingDef& def) {
  return {def.method, def.stiffness, def.damping, def.alpha};
}

// The coupling law in any one frame: faceNormal k, the position offset
// dr = r_p - r_h and the velocity offset dv = v_p - v_h must share it, and so
// does the force returned. Inline: it runs in every integrator stage.
template <class T>
inline Real3Of<T> handForceOf(const CouplingLawOf<T>& law, const Real3Of<T>& k, const Real3Of<T>& dr,
                              const Real3Of<T>& dv) {
  Real3Of<T> force = -law.stiffness * dr - law.damping * dv;
  if (law.method == ForceMethod::M3) {
    // R diag(k, k, alpha k) R^T = k I + (alpha - 1) k k_o k_o^T: only the
    // normal component is stiffer, so no rotation to the body frame is needed.
    force = force - ((law.alpha - 1.0) * (law.stiffness * dot(k, dr) + law.damping * dot(k, dv))) * k;
  }
  return force;
}
inline Real3 handForce(const CouplingDef& def, const Real3& k, const Real3& dr, const Real3& dv) {
  return handForceOf(couplingLawOf(def), k, dr, dv);
}

// The part of F_h that drives the model: all of it for M2 and M3, the in-face
// part for M1 (eq. 42).
template <class T>
inline Real3Of<T> modelForceOf(ForceMethod method, const Real3Of<T>& k, const Real3Of<T>& hand) {
  return method == ForceMethod::M1 ? hand - dot(k, hand) * k : hand;
}
inline Real3 modelForce(const CouplingDef& def, const Real3& k, const Real3& hand) {
  return modelForceOf(def.method, k, hand);
}

// Absolute position and velocity of the mass point in the base frame,
// r_p = r_o + rho_p and v_p = w x (rho_p - rho_c) + rho_p' (Sec. 3.2), for
// angular velocity w in the base frame.
struct PointKinematics {
  Vec3 position;
  Vec3 velocity;
};
PointKinematics pointKinematics(const RollingGeometry& g, double radius, double u_a, double v_a,
                                const Vec3& omega);

const char* forceMethodName(ForceMethod m);
// The method named "M1", "M2" or "M3"; nullopt for anything else.
std::optional<ForceMethod> forceMethodFromName(std::string_view name);

}  // namespace hemiroll::physics
