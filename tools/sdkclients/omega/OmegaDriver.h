#pragma once
// A Force Dimension omega.3 / omega.6 (or any DHD device) through the DHD
// API. DHD has no scheduler of its own: a PacedServoThread reads, ticks and
// writes at the bridge's rate.

#include <atomic>

#include "tools/sdkclients/DeviceDriver.h"
#include "tools/sdkclients/PacedServoThread.h"

namespace hemiroll::sdkclients {

class OmegaDriver final : public DeviceDriver {
 public:
  // DHD reports no continuous force; the omega.3's published 12 N stands
  // unless the command line gives the profile's.
  explicit OmegaDriver(double continuousForce = 12.0) : continuousForce_(continuousForce) {}
  const char* name() const override { return "Force Dimension DHD"; }
  double continuousForce() const override { return continuousForce_; }
  AxisMap axes() const override { return forceDimensionAxes(); }
  std::string open() override;
  std::string startServo(ServoTick& tick) override;
  std::string setForcesEnabled(bool on) override;
  void stopServo() override;
  void close() override;

 private:
  void step(ServoTick& tick, std::int64_t nowNs);

  int id_ = -1;
  double continuousForce_;
  PacedServoThread loop_;
  std::atomic<bool> fault_{false};
};

}  // namespace hemiroll::sdkclients
