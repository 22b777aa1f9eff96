#include "engine/haptics/devices/MouseDevice.h"

#include <stdexcept>
#include <string>

namespace hemiroll::haptics {

MouseDeviceDef mouseHandDef(const MouseDeviceDef& base, const HandSpringDef& hand) {
  MouseDeviceDef d = base;
  d.hand = true;
  d.handSpring = hand;
  d.spec = kMouseHandSpec;
  return d;
}

MouseDevice::MouseDevice(const MouseDeviceDef& def) : def_(def), velocity_(def.velocity), hand_(def.handSpring) {
  if (def.hand) {
    if (const std::string bad = validateHandSpring(def.handSpring); !bad.empty())
      throw std::invalid_argument("mouse-hand: " + bad);
  }
}

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
  const bool jumped = current_.jumps != lastJumps_;
  if (jumped) {
    velocity_.reset(now, p);
    lastJumps_ = current_.jumps;
  }
  DeviceReading r;
  r.position = p;
  r.velocity = velocity_.update(now, p, current_.serial != lastSerial_);
  if (def_.hand) {
    // The hand goes where the pointer jumped (put on the mass point, taken
    // over): a new path, not a motion of the hand.
    if (jumped || handTime_ < 0.0) {
      hand_.reset(p);
      r.newPath = handTime_ >= 0.0;
    } else {
      hand_.step(p, r.velocity, lastForce_, now - handTime_);
    }
    handTime_ = now;
    r.position = hand_.position();
    r.velocity = hand_.velocity();
  }
  r.buttons = current_.buttons;
  r.fresh = true;
  lastSerial_ = current_.serial;
  return r;
}

}  // namespace hemiroll::haptics
