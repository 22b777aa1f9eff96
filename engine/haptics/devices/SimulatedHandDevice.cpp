#include "engine/haptics/devices/SimulatedHandDevice.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace hemiroll::haptics {

SimulatedHandDevice::SimulatedHandDevice(IntentFunction intent, const HandModelDef& hand, const DeviceSpec& spec,
                                         double t0)
    : intent_(std::move(intent)), hand_(hand), spec_(spec), time_(t0) {
  if (!intent_) throw std::invalid_argument("SimulatedHandDevice: empty intent function");
  if (!(hand.mass > 0.0) || !(hand.stiffness >= 0.0) || !(hand.damping >= 0.0) || !(hand.maxStep > 0.0))
    throw std::invalid_argument("SimulatedHandDevice: hand mass and maxStep must be positive, gains non-negative");
  position_ = intent_(t0).position;
}

DeviceReading SimulatedHandDevice::read(double t) {
  // Sub-steps no longer than maxStep; the intent is sampled at each start.
  while (time_ < t) {
    const double h = std::min(hand_.maxStep, t - time_);
    const Intent goal = intent_(time_);
    const Vec3 accel = (hand_.stiffness * (goal.position - position_) + hand_.damping * (goal.velocity - velocity_) +
                        force_) /
                       hand_.mass;
    velocity_ += h * accel;
    position_ += h * velocity_;
    time_ += h;
  }
  DeviceReading r;
  r.position = position_;
  r.velocity = velocity_;
  return r;
}

}  // namespace hemiroll::haptics
