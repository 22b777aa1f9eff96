#include "engine/haptics/VelocityEstimator.h"

#include <cmath>
#include <stdexcept>

namespace hemiroll::haptics {

VelocityEstimator::VelocityEstimator(const VelocityFilterDef& def) : def_(def) {
  if (!(def.timeConstant > 0.0) || !(def.maxSpeed > 0.0) || !(def.holdTime > 0.0))
    throw std::invalid_argument("VelocityEstimator: timeConstant, maxSpeed and holdTime must be positive");
}

void VelocityEstimator::reset(double t, const Vec3& position) {
  started_ = true;
  lastUpdate_ = lastSampleTime_ = t;
  lastSample_ = position;
  raw_ = velocity_ = Vec3::Zero();
}

const Vec3& VelocityEstimator::update(double t, const Vec3& position, bool newSample) {
  if (!started_ || !position.allFinite()) {
    reset(t, position.allFinite() ? position : lastSample_);
    return velocity_;
  }
  if (newSample) {
    const double dt = t - lastSampleTime_;
    if (dt > 0.0) {
      raw_ = (position - lastSample_) / dt;
      const double speed = raw_.norm();
      if (speed > def_.maxSpeed) raw_ *= def_.maxSpeed / speed;
      lastSample_ = position;
      lastSampleTime_ = t;
    }
    // dt <= 0: two samples within one clock reading; the later difference
    // covers both, since lastSample_ is kept.
  } else if (t - lastSampleTime_ > def_.holdTime) {
    raw_ = Vec3::Zero();
  }
  const double h = t - lastUpdate_;
  lastUpdate_ = t;
  if (h > 0.0) velocity_ += (1.0 - std::exp(-h / def_.timeConstant)) * (raw_ - velocity_);
  return velocity_;
}

}  // namespace hemiroll::haptics
