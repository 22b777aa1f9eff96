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
  hand_.reset(intent_(t0).position);
}

DeviceReading SimulatedHandDevice::read(double t) {
  // Sub-steps no longer than maxStep; the intent is sampled at each start.
  while (time_ < t) {
    const double h = std::min(hand_.def().maxStep, t - time_);
    const Intent goal = intent_(time_);
    hand_.step(goal.position, goal.velocity, force_, h);
    time_ += h;
  }
  DeviceReading r;
  r.position = hand_.position();
  r.velocity = hand_.velocity();
  return r;
}

}  // namespace hemiroll::haptics
