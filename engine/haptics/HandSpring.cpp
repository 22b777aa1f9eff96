#include "engine/haptics/HandSpring.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::haptics {

std::string validateHandSpring(const HandSpringDef& d) {
  if (!(d.mass > 0.0) || !std::isfinite(d.mass)) return "hand mass must be a positive number of kg";
  if (!(d.stiffness > 0.0) || !std::isfinite(d.stiffness)) return "hand stiffness must be a positive number of N/m";
  if (!(d.damping >= 0.0) || !std::isfinite(d.damping)) return "hand damping must be a number of N s/m >= 0";
  if (!(d.maxStep > 0.0) || !(d.maxStep <= 0.01)) return "hand maxStep must be in (0, 0.01] s";
  // The explicit part is stable for h < 2 / omega_n; keep a factor of 4.
  if (d.maxStep * std::sqrt(d.stiffness / d.mass) > 0.5)
    return "hand maxStep is too long for its stiffness and mass (maxStep sqrt(k/m) must be <= 0.5)";
  if (!(d.maxGap >= d.maxStep) || !std::isfinite(d.maxGap)) return "hand maxGap must be at least maxStep";
  return "";
}

void HandSpring::reset(const Vec3& at) {
  if (!at.allFinite()) return;
  position_ = at;
  velocity_.setZero();
}

void HandSpring::step(const Vec3& pointer, const Vec3& pointerVelocity, const Vec3& force, double dt) {
  if (!pointer.allFinite() || !pointerVelocity.allFinite() || !force.allFinite() || !(dt > 0.0)) return;
  double left = std::min(dt, def_.maxGap);
  while (left > 0.0) {
    const double h = std::min(def_.maxStep, left);
    const Vec3 accel =
        (def_.stiffness * (pointer - position_) + def_.damping * (pointerVelocity - velocity_) + force) / def_.mass;
    velocity_ += h * accel;
    position_ += h * velocity_;
    left -= h;
  }
}

}  // namespace hemiroll::haptics
