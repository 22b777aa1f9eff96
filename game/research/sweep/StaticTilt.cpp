#include "game/research/sweep/StaticTilt.h"

#include <cmath>
#include <numbers>

namespace hemiroll::game {

double staticTilt(const physics::HemisphereParams& p, double d) {
  if (!(d > 0.0) || !(p.pointMass > 0.0) || !(p.gravity > 0.0)) return 0.0;
  const auto residual = [&](double t) {
    return p.pointMass * std::cos(t) * (d - p.radius * std::sin(t)) - 0.375 * p.radius * p.shellMass * std::sin(t);
  };
  double lo = 0.0, hi = 0.5 * std::numbers::pi;
  while (true) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // no double in between
    (residual(mid) > 0.0 ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace hemiroll::game
