#include "engine/haptics/devices/MouseDevice.h"

namespace hemiroll::haptics {

MouseDevice::MouseDevice(const MouseDeviceDef& def) : def_(def), velocity_(def.velocity) {}

void MouseDevice::setPointer(const Vec3& position, std::uint32_t buttons, bool jump) {
  if (!position.allFinite()) return;  // a broken event never reaches the loop
  PointerSample s;
  s.position = {position.x(), position.y(), position.z()};
  s.buttons = buttons;
  s.serial = ++serial_;
  if (jump) ++jumps_;
  s.jumps = jumps_;
  pointer_.write(s);
}

DeviceReading MouseDevice::read(double /*t: the mouse runs on wall time*/) {
  PointerSample s;
  if (pointer_.read(s)) current_ = s;
  const Vec3 p(current_.position[0], current_.position[1], current_.position[2]);
  const double now = static_cast<double>(def_.clock()) * 1e-9;
  if (current_.jumps != lastJumps_) {
    velocity_.reset(now, p);
    lastJumps_ = current_.jumps;
  }
  DeviceReading r;
  r.position = p;
  r.velocity = velocity_.update(now, p, current_.serial != lastSerial_);
  r.buttons = current_.buttons;
  r.fresh = true;
  lastSerial_ = current_.serial;
  return r;
}

}  // namespace hemiroll::haptics
