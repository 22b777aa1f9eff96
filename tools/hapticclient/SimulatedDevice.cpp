#include "tools/hapticclient/SimulatedDevice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "engine/haptics/ForceClamp.h"

namespace hemiroll::hapticclient {

using haptics::Vec3;

namespace {

haptics::HandModelDef withHandle(haptics::HandModelDef hand, double handleMass) {
  hand.mass += handleMass;
  return hand;
}

double quantised(double x, double step) { return step > 0.0 ? step * std::round(x / step) : x; }

}  // namespace

DeviceModel::DeviceModel(haptics::SimulatedHandDevice::IntentFunction intent, const DeviceModelDef& def)
    : def_(def), hand_(std::move(intent), withHandle(def.hand, def.handleMass)) {}

void DeviceModel::setForce(const Vec3& force) {
  rendered_ = def_.peakForce > 0.0 ? haptics::clampForce(force, def_.peakForce).force : force;
}

haptics::DeviceReading DeviceModel::read(double t) {
  // Friction opposes the handle's motion over the coming period (zero-order
  // hold, as the motors hold the force), never more than stops it within
  // the period (it brakes; it does not push back).
  const Vec3 v = hand_.velocity();
  const double speed = v.norm();
  const double dt = t - readTime_;
  const double stopping = dt > 0.0 ? (def_.hand.mass + def_.handleMass) * speed / dt : 0.0;
  const double size = std::min(def_.friction, stopping);
  const Vec3 friction = speed > 0.0 ? Vec3(-size / speed * v) : Vec3::Zero();
  readTime_ = t;
  hand_.sendForce(rendered_ + friction);
  haptics::DeviceReading r = hand_.read(t);
  const Vec3 p(quantised(r.position.x(), def_.resolution), quantised(r.position.y(), def_.resolution),
               quantised(r.position.z(), def_.resolution));
  if (def_.resolution > 0.0) {
    r.velocity = lastTime_ >= 0.0 && t > lastTime_ ? Vec3((p - lastPosition_) / (t - lastTime_)) : Vec3::Zero();
    r.position = p;
  }
  lastPosition_ = p;
  lastTime_ = t;
  return r;
}

OutgoingLink::OutgoingLink(const LinkFaultsDef& def) : def_(def), random_(def.seed) {}

void OutgoingLink::enqueue(const Datagram& d, std::int64_t release) {
  auto at = queue_.end();
  while (at != queue_.begin() && std::prev(at)->release > release) --at;
  queue_.insert(at, Pending{release, d});
}

void OutgoingLink::push(const Datagram& d, std::int64_t now) {
  if (def_.loss > 0.0 && unit_(random_) < def_.loss) {
    ++lost_;
    return;
  }
  const auto delay = static_cast<std::int64_t>(def_.jitter * unit_(random_) * 1e9);
  if (holding_) {  // the held one goes right after this one
    enqueue(d, now + delay);
    enqueue(held_, now + delay);
    holding_ = false;
    return;
  }
  if (def_.reorder > 0.0 && unit_(random_) < def_.reorder) {
    held_ = d;
    holding_ = true;
    ++reordered_;
    return;
  }
  enqueue(d, now + delay);
}

std::int64_t OutgoingLink::nextRelease() const {
  return queue_.empty() ? std::numeric_limits<std::int64_t>::max() : queue_.front().release;
}

void StepWatch::stepSent(std::uint32_t sequence, std::int64_t now) {
  waiting_ = true;
  stepSequence_ = sequence;
  stepSentNs_ = now;
  before_ = last_;
}

void StepWatch::forceReceived(std::uint32_t answers, const Vec3& force, std::int64_t now) {
  last_ = force;
  if (!waiting_ || !haptics::udp::sequenceAfter(answers + 1, stepSequence_)) return;  // answers a state before the step
  if ((force - before_).norm() <= threshold_) return;
  latencies_.push_back(static_cast<double>(now - stepSentNs_) * 1e-9);
  waiting_ = false;
}

}  // namespace hemiroll::hapticclient
