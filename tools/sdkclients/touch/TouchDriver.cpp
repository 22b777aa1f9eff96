#include "tools/sdkclients/touch/TouchDriver.h"

#include "engine/haptics/ServoClock.h"

namespace hemiroll::sdkclients {

namespace {

// "" when the toolkit reports no error since the last call, else the call
// named with the toolkit's codes (hduPrintError's words are in HDU, a
// library the client does not link).
std::string lastError(const char* call) {
  const HDErrorInfo e = hdGetError();
  if (!HD_DEVICE_ERROR(e)) return {};
  return std::string(call) + " failed: HD error " + std::to_string(e.errorCode) + " (internal " +
         std::to_string(e.internalErrorCode) + ")";
}

}  // namespace

std::string TouchDriver::open() {
  device_ = hdInitDevice(HD_DEFAULT_DEVICE);
  if (std::string why = lastError("hdInitDevice"); !why.empty()) {
    device_ = HD_INVALID_HANDLE;
    return why + "; is the Touch plugged in and set up (Touch_Setup)?";
  }
  hdGetDoublev(HD_NOMINAL_MAX_CONTINUOUS_FORCE, &continuousForce_);
  if (!lastError("hdGetDoublev(HD_NOMINAL_MAX_CONTINUOUS_FORCE)").empty()) continuousForce_ = 0.0;
  return {};
}

HDCallbackCode HDCALLBACK TouchDriver::servo(void* self) {
  auto& d = *static_cast<TouchDriver*>(self);
  static thread_local haptics::SteadyServoClock clock;
  hdBeginFrame(hdGetCurrentDevice());
  DeviceSample s;
  hdGetDoublev(HD_CURRENT_POSITION, s.position.data());
  hdGetDoublev(HD_CURRENT_VELOCITY, s.velocity.data());
  HDint buttons = 0;
  hdGetIntegerv(HD_CURRENT_BUTTONS, &buttons);
  s.buttons = static_cast<std::uint32_t>(buttons);
  s.deviceFault = d.fault_.load(std::memory_order_relaxed);
  const Vec3 f = d.tick_->tick(s, clock.now());
  hdSetDoublev(HD_CURRENT_FORCE, f.data());
  hdEndFrame(hdGetCurrentDevice());
  // An error in this frame (a force the amplifiers refused, a lost device)
  // is sent with the next sample: the bridge then stops, and says why.
  d.fault_.store(HD_DEVICE_ERROR(hdGetError()), std::memory_order_relaxed);
  return HD_CALLBACK_CONTINUE;
}

std::string TouchDriver::startServo(ServoTick& tick) {
  tick_ = &tick;
  callback_ = hdScheduleAsynchronous(&TouchDriver::servo, this, HD_MAX_SCHEDULER_PRIORITY);
  if (std::string why = lastError("hdScheduleAsynchronous"); !why.empty()) return why;
  scheduled_ = true;
  hdStartScheduler();
  if (std::string why = lastError("hdStartScheduler"); !why.empty()) return why;
  schedulerRunning_ = true;
  return {};
}

std::string TouchDriver::setForcesEnabled(bool on) {
  if (on) hdEnable(HD_FORCE_OUTPUT);
  else hdDisable(HD_FORCE_OUTPUT);
  return lastError(on ? "hdEnable(HD_FORCE_OUTPUT)" : "hdDisable(HD_FORCE_OUTPUT)");
}

void TouchDriver::stopServo() {
  if (schedulerRunning_) hdStopScheduler();
  if (scheduled_) hdUnschedule(callback_);
  schedulerRunning_ = scheduled_ = false;
}

void TouchDriver::close() {
  stopServo();
  if (device_ != HD_INVALID_HANDLE) hdDisableDevice(device_);
  device_ = HD_INVALID_HANDLE;
}

}  // namespace hemiroll::sdkclients
