#pragma once
// A 3D Systems Touch / Touch X (or any OpenHaptics device) through the HD
// API: the toolkit's own servo scheduler calls the tick at its rate (1 kHz),
// inside a frame (hdBeginFrame/hdEndFrame), as the toolkit requires.

#include <atomic>

#include "tools/sdkclients/DeviceDriver.h"

#include <HD/hd.h>

namespace hemiroll::sdkclients {

class TouchDriver final : public DeviceDriver {
 public:
  const char* name() const override { return "OpenHaptics"; }
  double continuousForce() const override { return continuousForce_; }
  AxisMap axes() const override { return openHapticsAxes(); }
  std::string open() override;
  std::string startServo(ServoTick& tick) override;
  std::string setForcesEnabled(bool on) override;
  void stopServo() override;
  void close() override;

 private:
  static HDCallbackCode HDCALLBACK servo(void* self);

  HHD device_ = HD_INVALID_HANDLE;
  HDSchedulerHandle callback_ = 0;
  bool scheduled_ = false, schedulerRunning_ = false;
  double continuousForce_ = 0.0;
  ServoTick* tick_ = nullptr;
  std::atomic<bool> fault_{false};
};

}  // namespace hemiroll::sdkclients
