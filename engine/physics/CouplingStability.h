#pragma once
// Where an explicit step is too long for the haptic coupling, and how many
// substeps make it stable (docs/PHYSICS.md, "Where explicit methods become
// unstable").
//
// The coupling is a spring-damper between the proxy and the mass point. The
// mass it moves is at least m_p in every direction (the kinetic energy of the
// system is at least (1/2) m_p |v_p|^2, so the effective mass seen along any
// direction is >= m_p), so the fastest mode it adds is bounded by that of the
// scalar oscillator m_p x'' + c x' + k x = 0 with the stiffest gains in use
// (k = alpha k_r and c = alpha k_v along the face normal for M3 with
// alpha > 1; M1 only acts in the face plane, gain 1). Its eigenvalues
// lambda = (-c +- sqrt(c^2 - 4 k m_p)) / (2 m_p) are the estimate: for light
// damping |lambda| = sqrt(k / m_p) (natural frequency), for heavy damping the
// fast root tends to -c / m_p (damping rate).
//
// An explicit method is stable on that mode when h lambda lies in its
// stability region. For RK4 the region's boundary along the ray of lambda is
// found numerically from R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24, |R(z)| <= 1
// (2.785 on the negative real axis, 2 sqrt 2 on the imaginary axis).
//
// Policy (SubsteppingIntegrator.h): a requested step h longer than
// kSafety * (ray limit) / |lambda| is split into n = ceil(h / hMax) equal
// substeps, deterministically; n = 1 (no change at all) otherwise. The safety
// factor leaves room for the rest of the dynamics (rocking, spin), which the
// estimate does not include.

#include <string_view>

#include "engine/physics/ForceCoupling.h"

namespace hemiroll::physics {

struct CouplingModes {
  double naturalFrequency;  // sqrt(k / m_p) of the stiffest direction [rad/s]
  double dampingRate;       // c / m_p of the stiffest direction [1/s]
  double lambdaRe;          // the eigenvalue of largest modulus, real part [1/s]
  double lambdaIm;          // and imaginary part (>= 0) [rad/s]
  double magnitude() const;
};

// The fastest mode the coupling adds, for a mass point of pointMass [kg].
CouplingModes couplingModes(const CouplingDef& def, double pointMass);

// RK4's stability limit along the ray of angle theta from the positive real
// axis (theta in [pi/2, pi]): the largest s with |R(s e^{i theta})| <= 1 on
// all of [0, s].
double rk4StabilityRadius(double theta);

struct StepPolicy {
  // Fraction of the stability limit a (sub)step may use.
  static constexpr double kSafety = 0.5;

  double maxStableStep;  // [s]; +inf when the method has no limit here
  int substeps;          // for the requested step: 1 = step as asked
};

// The step policy for a fixed-step method by registry name, a coupling, a
// mass point and a requested step h. Methods without a known explicit limit
// (the adaptive ones, which control their own step) get substeps = 1.
StepPolicy couplingStepPolicy(std::string_view integrator, const CouplingDef& def, double pointMass, double h);

}  // namespace hemiroll::physics
