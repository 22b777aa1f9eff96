#include "engine/autopilot/Goal.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::autopilot {

namespace {

constexpr int kPsi = physics::force_slot::psi;

double slotError(const Goal& goal, const physics::ForceDrivenState& x, int slot) {
  const auto i = static_cast<std::size_t>(slot);
  double d = x[slot] - goal.target[i];
  if (slot == kPsi) d = std::remainder(d, 2.0 * M_PI);
  return std::abs(d) / goal.tolerance[i];
}

// (|omega| - target) / tolerance, signed.
double omegaNormError(const Goal& goal, const physics::ForceDrivenState& x) {
  const double w = std::sqrt(x[4] * x[4] + x[5] * x[5] + x[6] * x[6]);
  return (w - goal.omegaNormTarget) / goal.omegaNormTolerance;
}

}  // namespace

double normalisedError(const Goal& goal, const physics::ForceDrivenState& x) {
  double e = 0.0;
  for (int slot = 0; slot < 12; ++slot)
    if (goal.set[static_cast<std::size_t>(slot)]) e = std::max(e, slotError(goal, x, slot));
  if (goal.omegaNormSet) e = std::max(e, std::abs(omegaNormError(goal, x)));
  return std::isfinite(e) ? e : 1e30;  // a non-finite state is as far as it gets
}

double squaredError(const Goal& goal, const physics::ForceDrivenState& x) {
  double sum = 0.0;
  for (int slot = 0; slot < 12; ++slot) {
    if (!goal.set[static_cast<std::size_t>(slot)]) continue;
    const double e = slotError(goal, x, slot);
    sum += e * e;
  }
  if (goal.omegaNormSet) sum += omegaNormError(goal, x) * omegaNormError(goal, x);
  return std::isfinite(sum) ? sum : 1e30;
}

bool inForbiddenZone(const Goal& goal, const physics::ForceDrivenState& x) {
  const physics::Vec2 contact(x[physics::force_slot::u_a], x[physics::force_slot::v_a]);
  for (int i = 0; i < goal.zoneCount; ++i)
    if (goal.zones[static_cast<std::size_t>(i)].clearance(contact) <= 0.0) return true;
  return false;
}


}  // namespace hemiroll::autopilot
