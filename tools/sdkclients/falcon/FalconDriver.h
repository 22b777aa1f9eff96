#pragma once
// A Novint Falcon through libnifalcon: the firmware loaded (from the file a
// lab gives) and the grip homed at open, then a PacedServoThread runs one
// libnifalcon I/O loop per bridge tick.

#include <atomic>
#include <memory>
#include <string>

#include "tools/sdkclients/DeviceDriver.h"
#include "tools/sdkclients/PacedServoThread.h"

namespace libnifalcon {
class FalconDevice;
}

namespace hemiroll::sdkclients {

struct FalconDriverDef {
  std::string firmwareFile;       // loaded when the Falcon has none (libnifalcon's firmware folder)
  double homingTimeout = 30.0;    // [s] for the person to move the grip in and out
  // [N]: devices/falcon.lua's continuous figure; Novint publishes only a
  // peak of 8.9 N (more than 2 lbf), which a Falcon cannot hold for long.
  double continuousForce = 3.0;
};

class FalconDriver final : public DeviceDriver {
 public:
  explicit FalconDriver(FalconDriverDef def);
  ~FalconDriver() override;
  const char* name() const override { return "libnifalcon"; }
  double continuousForce() const override { return def_.continuousForce; }
  AxisMap axes() const override { return libnifalconAxes(); }
  std::string open() override;
  std::string startServo(ServoTick& tick) override;
  std::string setForcesEnabled(bool on) override;
  void stopServo() override;
  void close() override;

 private:
  void step(ServoTick& tick, std::int64_t nowNs);

  FalconDriverDef def_;
  std::unique_ptr<libnifalcon::FalconDevice> device_;
  bool open_ = false;
  std::atomic<bool> forcesOn_{false}, fault_{false};
  Vec3 lastPosition_{};
  std::int64_t lastNs_ = 0;
  PacedServoThread loop_;
};

}  // namespace hemiroll::sdkclients
