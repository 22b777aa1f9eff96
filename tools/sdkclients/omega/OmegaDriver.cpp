#include "tools/sdkclients/omega/OmegaDriver.h"

#include <dhdc.h>

namespace hemiroll::sdkclients {

namespace {

std::string failed(const char* call) {
  const char* why = dhdErrorGetLastStr();
  return std::string(call) + " failed: " + (why ? why : "no reason given");
}

constexpr std::int64_t kPeriodNs = 1'000'000;  // the bridge's 1 kHz

}  // namespace

std::string OmegaDriver::open() {
  id_ = dhdOpen();
  if (id_ < 0) return failed("dhdOpen") + "; is the device on, plugged in and not open in another program?";
  return {};
}

void OmegaDriver::step(ServoTick& tick, std::int64_t nowNs) {
  const char id = static_cast<char>(id_);
  DeviceSample s;
  const bool read = dhdGetPosition(&s.position[0], &s.position[1], &s.position[2], id) >= 0 &&
                    dhdGetLinearVelocity(&s.velocity[0], &s.velocity[1], &s.velocity[2], id) >= 0;
  const int buttons = dhdGetButtonMask(id);
  s.buttons = buttons > 0 ? static_cast<std::uint32_t>(buttons) : 0u;
  s.deviceFault = !read || fault_.load(std::memory_order_relaxed);
  const Vec3 f = tick.tick(s, nowNs);
  // A saturated motor (DHD_MOTOR_SATURATED) is not a fault: the SDK scaled
  // the force down, as the link did already to the continuous force.
  fault_.store(dhdSetForce(f[0], f[1], f[2], id) < 0, std::memory_order_relaxed);
}

std::string OmegaDriver::startServo(ServoTick& tick) {
  loop_.start(kPeriodNs, [this, &tick](std::int64_t now) { step(tick, now); });
  return {};
}

std::string OmegaDriver::setForcesEnabled(bool on) {
  if (dhdEnableForce(on ? DHD_ON : DHD_OFF, static_cast<char>(id_)) < 0) return failed("dhdEnableForce");
  return {};
}

void OmegaDriver::stopServo() { loop_.stop(); }

void OmegaDriver::close() {
  stopServo();
  if (id_ >= 0) dhdClose(static_cast<char>(id_));
  id_ = -1;
}

}  // namespace hemiroll::sdkclients
