#pragma once
// Where things are, read from a 12-state: the positions the game draws, the
// mouse aims at and the tools plot. Pure kinematics (eq. 6): no dynamics,
// no coupling, nothing per tick that a model needs.

#include <array>

#include "engine/physics/StateLayout.h"

namespace hemiroll::physics {

// A 12-state as it crosses threads and files (plain arrays: ServoSnapshot,
// RecordRow) read back as the model's vector.
inline ForceDrivenState forceStateOf(const std::array<double, 12>& a) {
  return Eigen::Map<const ForceDrivenState>(a.data());
}

// A vector as it crosses threads and files (ServoSnapshot's and the bot
// observation's plain triples) and back.
inline Vec3 vec3Of(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
inline std::array<double, 3> tripleOf(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

// The mass point in the base frame [m]: the sphere centre (u_a, v_a, R)
// plus R (x_p, y_p, 0).
Vec3 massPointPosition(const ForceDrivenState& x, double radius);

}  // namespace hemiroll::physics
