#include "engine/haptics/devices/ReplayDevice.h"

#include <utility>

namespace hemiroll::haptics {

ReplayDevice::ReplayDevice(std::vector<TickInput> inputs, const DeviceSpec& spec)
    : inputs_(std::move(inputs)), spec_(spec) {}

DeviceReading ReplayDevice::read(double /*t*/) {
  if (next_ >= inputs_.size()) {
    error_ = "replay log ended";
    last_.fresh = false;
    last_.newPath = false;
    return last_;
  }
  const TickInput& in = inputs_[next_++];
  last_.position = Vec3(in.position[0], in.position[1], in.position[2]);
  last_.velocity = Vec3(in.velocity[0], in.velocity[1], in.velocity[2]);
  last_.buttons = in.buttons;
  last_.fresh = in.fresh;
  last_.newPath = in.newPath;
  return last_;
}

}  // namespace hemiroll::haptics
