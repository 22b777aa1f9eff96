#pragma once
// A plain 3-vector for the hot path of the dynamics, over doubles or over
// lanes of doubles (LaneMath.h).
//
// Why not Eigen::Vector3d here: measured on the right-hand side of the
// 12-state model (tools/bench/PhysicsBench.cpp), the same arithmetic written
// with Eigen's fixed-size 3-vectors ran 1.8x slower than with plain doubles
// (GCC 12, -O3, SSE2): Eigen's expression templates keep 3-vectors in memory
// instead of registers. A struct of three numbers with inline operators
// compiles to the plain-double code. Eigen stays at the API boundary.
//
// Why a template: the batched integrator (BatchedRk4.h) runs the very same
// arithmetic with T a vector of lanes, one trajectory per lane. Written once,
// the scalar and the lane paths do the same operations in the same order, so
// every lane has the bits the scalar path gives (tests/physics/BatchedRk4Test).

#include <type_traits>

#include "engine/physics/StateLayout.h"

namespace hemiroll::physics {

template <class T>
struct Real3Of {
  T x, y, z;

  static Real3Of from(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
  Vec3 eigen() const { return {x, y, z}; }
};
using Real3 = Real3Of<double>;

// A double times lanes: the double is broadcast (GCC vector extensions).
template <class T>
concept Lanewise = !std::is_same_v<T, double>;

template <class T>
inline Real3Of<T> operator+(const Real3Of<T>& a, const Real3Of<T>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class T>
inline Real3Of<T> operator-(const Real3Of<T>& a, const Real3Of<T>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class T>
inline Real3Of<T> operator-(const Real3Of<T>& a) { return {-a.x, -a.y, -a.z}; }
template <class T>
inline Real3Of<T> operator*(T s, const Real3Of<T>& a) { return {s * a.x, s * a.y, s * a.z}; }
template <class T>
inline Real3Of<T> operator*(const Real3Of<T>& a, T s) { return {a.x * s, a.y * s, a.z * s}; }
template <Lanewise T>
inline Real3Of<T> operator*(double s, const Real3Of<T>& a) { return {s * a.x, s * a.y, s * a.z}; }
template <Lanewise T>
inline Real3Of<T> operator*(const Real3Of<T>& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
template <class T>
inline T dot(const Real3Of<T>& a, const Real3Of<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class T>
inline Real3Of<T> cross(const Real3Of<T>& a, const Real3Of<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// a x (a x v) = a (a.v) - v |a|^2: half the products of two cross products.
template <class T>
inline Real3Of<T> doubleCross(const Real3Of<T>& a, const Real3Of<T>& v) { return a * dot(a, v) - v * dot(a, a); }

// v in every lane of T (v itself for a double). v - (+0) is v for every v,
// -0 and NaN included, so each lane holds exactly v.
template <class T>
inline T broadcast(double v) {
  if constexpr (std::is_same_v<T, double>) return v;
  else return v - T{};
}

// In-face 2-vectors (face coordinates) on the hot path.
template <class T>
struct Real2Of {
  T x, y;

  static Real2Of from(const Vec2& v) { return {v.x(), v.y()}; }
  Vec2 eigen() const { return {x, y}; }
};
using Real2 = Real2Of<double>;

}  // namespace hemiroll::physics
