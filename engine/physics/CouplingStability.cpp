#include "engine/physics/CouplingStability.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace hemiroll::physics {

double CouplingModes::magnitude() const { return std::hypot(lambdaRe, lambdaIm); }

CouplingModes couplingModes(const CouplingDef& def, double pointMass) {
  const double gain = def.method == ForceMethod::M3 ? std::max(1.0, def.alpha) : 1.0;
  const double k = gain * def.stiffness, c = gain * def.damping, m = pointMass;
  const double disc = c * c - 4.0 * k * m;
  CouplingModes modes{std::sqrt(k / m), c / m, 0.0, 0.0};
  if (disc < 0.0) {
    modes.lambdaRe = -c / (2.0 * m);
    modes.lambdaIm = std::sqrt(-disc) / (2.0 * m);
  } else {
    modes.lambdaRe = -(c + std::sqrt(disc)) / (2.0 * m);  // the fast root
  }
  return modes;
}

double rk4StabilityRadius(double theta) {
  const std::complex<double> dir = std::polar(1.0, theta);
  auto stable = [&](double s) {
    const std::complex<double> z = s * dir;
    return std::abs(1.0 + z * (1.0 + z * (0.5 + z * (1.0 / 6.0 + z / 24.0)))) <= 1.0;
  };
  // Walk out in small steps to the first unstable point (the region is not
  // convex near the imaginary axis), then bisect.
  constexpr double kStride = 1e-3;
  double s = 0.0;
  while (s < 4.0 && stable(s + kStride)) s += kStride;
  double lo = s, hi = s + kStride;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return lo;
}

StepPolicy couplingStepPolicy(std::string_view integrator, const CouplingDef& def, double pointMass, double h) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (integrator != "rk4") return {kInf, 1};
  const CouplingModes modes = couplingModes(def, pointMass);
  const double magnitude = modes.magnitude();
  if (!(magnitude > 0.0)) return {kInf, 1};
  const double theta = std::atan2(modes.lambdaIm, modes.lambdaRe);
  const double maxStep = StepPolicy::kSafety * rk4StabilityRadius(theta) / magnitude;
  const double ratio = h / maxStep;
  const int substeps = ratio <= 1.0 ? 1 : static_cast<int>(std::min(std::ceil(ratio), 1e6));
  return {maxStep, substeps};
}

}  // namespace hemiroll::physics
