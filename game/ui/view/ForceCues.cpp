#include "game/ui/view/ForceCues.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::game {

namespace {

double clampStrain(double s) { return std::isnan(s) ? 0.0 : std::clamp(s, 0.0, 1.0); }

float mix(float a, float b, double t) { return static_cast<float>(a + (b - a) * t); }

}  // namespace

double couplingStrain(double force, double pointMass, double gravity) {
  const double weight = pointMass * gravity;
  if (std::isnan(force) || !(weight > 0.0) || !std::isfinite(weight)) return 0.0;
  return clampStrain(std::abs(force) / weight);
}

StrainRing strainRing(double strain, double hemisphereRadius) {
  const double s = clampStrain(strain);
  StrainRing ring;
  const double r = std::isfinite(hemisphereRadius) && hemisphereRadius > 0.0 ? hemisphereRadius : 0.0;
  ring.radius = r * (kRingMinRadii + (kRingMaxRadii - kRingMinRadii) * std::sqrt(s));
  // Saturated stops all the way (a straight blend of blue into yellow
  // passes through grey, which reads as nothing): blue, green, yellow, red.
  struct Stop {
    double at;
    std::array<float, 4> colour;
  };
  constexpr Stop kStops[] = {{0.0, {0.15f, 0.45f, 1.0f, 0.9f}},
                             {0.075, {0.1f, 0.85f, 0.3f, 0.9f}},
                             {0.15, {1.0f, 0.85f, 0.2f, 0.95f}},
                             {0.4, {1.0f, 0.2f, 0.15f, 1.0f}}};
  ring.colour = kStops[3].colour;
  for (int k = 0; k + 1 < 4; ++k) {
    if (s > kStops[k + 1].at) continue;
    const double t = (s - kStops[k].at) / (kStops[k + 1].at - kStops[k].at);
    for (std::size_t i = 0; i < 4; ++i) ring.colour[i] = mix(kStops[k].colour[i], kStops[k + 1].colour[i], t);
    break;
  }
  return ring;
}

double strainPitch(double strain) { return 180.0 * std::pow(4.0, clampStrain(strain)); }

double strainRumble(double strain, double limit) {
  const double l = std::isfinite(limit) ? std::clamp(limit, 0.0, 1.0) : 0.0;
  return l * clampStrain(strain);
}

}  // namespace hemiroll::game
