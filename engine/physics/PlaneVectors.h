#pragma once
// Small operations on vectors of the plane (the floor, the face) that the
// feedback laws of the autopilot and the human model share.

#include <cmath>

#include "engine/physics/StateLayout.h"

namespace hemiroll::physics {

// v, shortened to `limit` if it is longer.
inline Vec2 limitedTo(const Vec2& v, double limit) {
  const double n = v.norm();
  return n > limit ? Vec2(v * (limit / n)) : v;
}

// v turned anticlockwise (seen from above) by `angle` [rad].
inline Vec2 turnedBy(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace hemiroll::physics
