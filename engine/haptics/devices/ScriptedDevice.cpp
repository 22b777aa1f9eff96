#include "engine/haptics/devices/ScriptedDevice.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace hemiroll::haptics {

ScriptedDevice::ScriptedDevice(PoseFunction pose, const DeviceSpec& spec) : spec_(spec), pose_(std::move(pose)) {
  if (!pose_) throw std::invalid_argument("ScriptedDevice: empty pose function");
}

ScriptedDevice::ScriptedDevice(std::vector<PoseSample> samples, const DeviceSpec& spec)
    : spec_(spec), samples_(std::move(samples)) {
  if (samples_.empty()) throw std::invalid_argument("ScriptedDevice: no samples");
  for (std::size_t i = 1; i < samples_.size(); ++i) {
    if (!(samples_[i].time > samples_[i - 1].time))
      throw std::invalid_argument("ScriptedDevice: sample times must increase");
  }
}

DeviceReading ScriptedDevice::read(double t) {
  if (t >= stallFrom_) {
    DeviceReading stale = last_;
    stale.fresh = false;
    return stale;
  }
  last_ = pose_ ? pose_(t) : fromTable(t);
  last_.fresh = true;
  return last_;
}

DeviceReading ScriptedDevice::fromTable(double t) const {
  DeviceReading r;
  if (t <= samples_.front().time) {
    r.position = samples_.front().position;
    return r;
  }
  if (t >= samples_.back().time) {
    r.position = samples_.back().position;
    return r;
  }
  // First sample later than t; the table is small and read once per tick.
  const auto hi = std::upper_bound(samples_.begin(), samples_.end(), t,
                                   [](double time, const PoseSample& s) { return time < s.time; });
  const auto lo = hi - 1;
  const double span = hi->time - lo->time;
  const double s = (t - lo->time) / span;
  r.position = lo->position + s * (hi->position - lo->position);
  r.velocity = (hi->position - lo->position) / span;
  return r;
}

}  // namespace hemiroll::haptics
