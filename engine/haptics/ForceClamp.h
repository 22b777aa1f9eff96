#pragma once
// The last line of defence before a force reaches a hand: whatever comes in
// (NaN, Inf, huge), what goes out is finite and no longer than the limit.

#include <cmath>

#include "engine/haptics/HapticDevice.h"

namespace hemiroll::haptics {

struct ClampResult {
  Vec3 force = Vec3::Zero();  // finite, |force| <= maxForce [N]
  bool nonFinite = false;     // the input had a NaN or Inf: force is zero, the caller faults
  bool clamped = false;       // the input was longer than the limit and was shortened
};

// maxForce must be finite and >= 0 (a non-finite or negative limit gives zero).
// The shortened force is scaled by maxForce / |F| and then checked again:
// rounding may leave it one ulp long, in which case it is scaled down once more.
inline ClampResult clampForce(const Vec3& force, double maxForce) {
  ClampResult r;
  if (!std::isfinite(force.x()) || !std::isfinite(force.y()) || !std::isfinite(force.z())) {
    r.nonFinite = true;
    return r;
  }
  if (!(maxForce > 0.0) || !std::isfinite(maxForce)) {
    r.clamped = force.squaredNorm() > 0.0;
    return r;
  }
  // Norm without overflow: components up to DBL_MAX square to Inf.
  const double big = force.cwiseAbs().maxCoeff();
  if (big == 0.0) return r;
  const Vec3 unit = force / big;
  const double length = big * unit.norm();  // may be Inf for huge inputs; then the force is clamped
  if (length <= maxForce) {
    r.force = force;
    return r;
  }
  r.clamped = true;
  r.force = (maxForce / unit.norm()) * unit;
  for (int i = 0; i < 4 && r.force.norm() > maxForce; ++i) r.force *= 1.0 - 1e-15;
  return r;
}

// Limits how fast the force may change: |F - previous| <= maxStep.
inline Vec3 limitForceStep(const Vec3& previous, const Vec3& target, double maxStep) {
  const Vec3 change = target - previous;
  const double length = change.norm();
  if (length <= maxStep) return target;
  return previous + (maxStep / length) * change;
}

}  // namespace hemiroll::haptics
