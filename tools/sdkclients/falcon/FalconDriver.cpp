#include "tools/sdkclients/falcon/FalconDriver.h"

#include <chrono>
#include <thread>
#include <type_traits>

#include <falcon/core/FalconDevice.h>
#include <falcon/firmware/FalconFirmwareNovintSDK.h>
#include <falcon/kinematic/FalconKinematicStamper.h>

namespace hemiroll::sdkclients {

namespace {

constexpr std::int64_t kPeriodNs = 1'000'000;  // the bridge's 1 kHz

// libnifalcon's releases take the force as double[3], boost::array or
// std::array, and count devices into int8_t or unsigned int: the parameter's
// own type is read off the member function, so one source builds on each.
template <class C, class A> A parameterOf(void (C::*)(A));
template <class C, class A> A parameterOf(bool (C::*)(A));

template <class Device> void writeForce(Device& device, const Vec3& f) {
  using Arg = std::remove_cvref_t<decltype(parameterOf(&Device::setForce))>;
  if constexpr (std::is_pointer_v<Arg>) {
    double raw[3] = {f[0], f[1], f[2]};
    device.setForce(raw);
  } else {
    device.setForce(Arg{{f[0], f[1], f[2]}});
  }
}

template <class Device> long deviceCount(Device& device) {
  std::remove_reference_t<decltype(parameterOf(&Device::getDeviceCount))> count{};
  return device.getDeviceCount(count) ? static_cast<long>(count) : -1;
}

}  // namespace

FalconDriver::FalconDriver(FalconDriverDef def) : def_(std::move(def)) {}
FalconDriver::~FalconDriver() { close(); }

std::string FalconDriver::open() {
  device_ = std::make_unique<libnifalcon::FalconDevice>();
  libnifalcon::FalconDevice& d = *device_;
  d.setFalconFirmware<libnifalcon::FalconFirmwareNovintSDK>();
  d.setFalconKinematic<libnifalcon::FalconKinematicStamper>();
  const long count = deviceCount(d);
  if (count <= 0) return count < 0 ? "getDeviceCount failed" : "no Falcon is connected (getDeviceCount found 0)";
  if (!d.open(0)) return "open(0) failed (error " + std::to_string(d.getErrorCode()) + "); is another program using it?";
  open_ = true;
  if (!d.isFirmwareLoaded()) {
    if (def_.firmwareFile.empty())
      return "the Falcon has no firmware loaded: give --falcon-firmware FILE (libnifalcon's firmware folder)";
    if (!d.setFirmwareFile(def_.firmwareFile)) return "setFirmwareFile(" + def_.firmwareFile + ") failed: no such file";
    if (!d.loadFirmware(10u, false)) return "loadFirmware failed 10 times (error " + std::to_string(d.getErrorCode()) + ")";
  }
  // Homing: the person moves the grip in and out; the encoders find their index.
  d.getFalconFirmware()->setHomingMode(true);
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(def_.homingTimeout);
  while (!d.getFalconFirmware()->isHomed()) {
    d.runIOLoop();
    if (std::chrono::steady_clock::now() > until)
      return "the grip was not homed within " + std::to_string(static_cast<int>(def_.homingTimeout)) +
             " s: move it all the way in and out, then start again";
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return {};
}

void FalconDriver::step(ServoTick& tick, std::int64_t nowNs) {
  libnifalcon::FalconDevice& d = *device_;
  const bool ok = d.runIOLoop();
  const auto p = d.getPosition();
  DeviceSample s;
  s.position = {p[0], p[1], p[2]};
  // libnifalcon gives no velocity: a backward difference over the period.
  if (lastNs_ != 0 && nowNs > lastNs_)
    for (int i = 0; i < 3; ++i) s.velocity[i] = (s.position[i] - lastPosition_[i]) * 1e9 / static_cast<double>(nowNs - lastNs_);
  lastPosition_ = s.position;
  lastNs_ = nowNs;
  s.deviceFault = !ok || fault_.load(std::memory_order_relaxed);
  const Vec3 f = tick.tick(s, nowNs);
  writeForce(d, forcesOn_.load(std::memory_order_acquire) ? f : Vec3{});
}

std::string FalconDriver::startServo(ServoTick& tick) {
  loop_.start(kPeriodNs, [this, &tick](std::int64_t now) { step(tick, now); });
  return {};
}

// libnifalcon has no amplifier switch: "off" is a zero force on every loop.
std::string FalconDriver::setForcesEnabled(bool on) {
  forcesOn_.store(on, std::memory_order_release);
  return {};
}

void FalconDriver::stopServo() {
  loop_.stop();
  if (open_) {
    writeForce(*device_, Vec3{});
    device_->runIOLoop();  // the zero reaches the motors before the port closes
  }
}

void FalconDriver::close() {
  stopServo();
  if (open_) device_->close();
  open_ = false;
}

}  // namespace hemiroll::sdkclients
