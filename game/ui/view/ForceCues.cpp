#include "game/ui/view/ForceCues.h"

#include <algorithm>
#include <cmath>
#include <tuple>

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
  constexpr std::array<float, 4> kCalm{0.35f, 0.65f, 1.0f, 0.8f}, kWarm{1.0f, 0.85f, 0.2f, 0.95f},
      kHot{1.0f, 0.2f, 0.15f, 1.0f};
  constexpr double kWarmAt = 0.15, kHotAt = 0.4;
  const auto& [from, to, t] = s < kWarmAt ? std::tuple{kCalm, kWarm, s / kWarmAt}
                                          : std::tuple{kWarm, kHot, std::min(1.0, (s - kWarmAt) / (kHotAt - kWarmAt))};
  for (int i = 0; i < 4; ++i) ring.colour[static_cast<std::size_t>(i)] = mix(from[i], to[i], t);
  return ring;
}

double strainPitch(double strain) { return 180.0 * std::pow(4.0, clampStrain(strain)); }

double strainRumble(double strain, double limit) {
  const double l = std::isfinite(limit) ? std::clamp(limit, 0.0, 1.0) : 0.0;
  return l * clampStrain(strain);
}

}  // namespace hemiroll::game
