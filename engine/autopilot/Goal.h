#pragma once
// What the current stage of a task asks for, as the autopilot sees it: a band
// per state slot (physics/StateLayout.h order) and optionally one on |omega|.
// The game fills it from its judge; the autopilot only reads it.

#include <array>

#include "engine/physics/PlaneZone.h"
#include "engine/physics/StateLayout.h"

namespace hemiroll::autopilot {

// A region of the plane the contact point must never enter.
using Zone = physics::PlaneZone;

struct Goal {
  static constexpr int kMaxZones = 8;
  std::array<double, 12> target{};
  std::array<double, 12> tolerance{};  // half-widths, > 0 where set
  std::array<bool, 12> set{};
  bool omegaNormSet = false;
  double omegaNormTarget = 0.0, omegaNormTolerance = 0.0;  // [rad/s]
  double hold = 0.0;  // how long the bands must hold [s]
  std::array<Zone, kMaxZones> zones{};  // forbidden to the contact point
  int zoneCount = 0;

  bool contactSet() const { return set[7] || set[8]; }
};

// Whether the contact point of x is inside a forbidden zone.
bool inForbiddenZone(const Goal& goal, const physics::ForceDrivenState& x);

// The largest |x - target| / tolerance over the set bands (psi modulo 2 pi,
// as the judge compares it): <= 1 means every band holds.
double normalisedError(const Goal& goal, const physics::ForceDrivenState& x);

// Sum of squared normalised errors over the set bands: a smooth measure for
// searches (normalisedError is their max).
double squaredError(const Goal& goal, const physics::ForceDrivenState& x);

}  // namespace hemiroll::autopilot
