#pragma once
// A plain 3-vector for the hot path of the dynamics.
//
// Why not Eigen::Vector3d here: measured on the right-hand side of the
// 12-state model (tools/bench/PhysicsBench.cpp), the same arithmetic written
// with Eigen's fixed-size 3-vectors ran 1.8x slower than with plain doubles
// (GCC 12, -O3, SSE2): Eigen's expression templates keep 3-vectors in memory
// instead of registers. A struct of three doubles with inline operators
// compiles to the plain-double code. Eigen stays at the API boundary.

#include "engine/physics/StateLayout.h"

namespace hemiroll::physics {

struct Real3 {
  double x, y, z;

  static Real3 from(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
  Vec3 eigen() const { return {x, y, z}; }
};

inline Real3 operator+(const Real3& a, const Real3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Real3 operator-(const Real3& a, const Real3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Real3 operator-(const Real3& a) { return {-a.x, -a.y, -a.z}; }
inline Real3 operator*(double s, const Real3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Real3 operator*(const Real3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(const Real3& a, const Real3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Real3 cross(const Real3& a, const Real3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// a x (a x v) = a (a.v) - v |a|^2: half the products of two cross products.
inline Real3 doubleCross(const Real3& a, const Real3& v) { return a * dot(a, v) - v * dot(a, a); }

}  // namespace hemiroll::physics

namespace hemiroll::physics {

// In-face 2-vectors (face coordinates) on the hot path.
struct Real2 {
  double x, y;

  static Real2 from(const Vec2& v) { return {v.x(), v.y()}; }
  Vec2 eigen() const { return {x, y}; }
};

}  // namespace hemiroll::physics
