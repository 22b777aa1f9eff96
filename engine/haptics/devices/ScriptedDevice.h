#pragma once
// A device whose pose is a function of the loop's time: a C++ callback or a
// table of samples (linear interpolation, velocity from the segment's slope,
// held at the ends). For headless runs, bots and tests. It records the last
// force it was sent, and tests can make it fail (error) or stall (stop
// delivering fresh samples from a given time on).

#include <functional>
#include <vector>

#include "engine/haptics/HapticDevice.h"

namespace hemiroll::haptics {

struct PoseSample {
  double time = 0.0;             // [s]
  Vec3 position = Vec3::Zero();  // device coordinates [m]
};

class ScriptedDevice final : public HapticDevice {
 public:
  using PoseFunction = std::function<DeviceReading(double t)>;

  ScriptedDevice(PoseFunction pose, const DeviceSpec& spec = {});
  // Samples in increasing time; at least one.
  ScriptedDevice(std::vector<PoseSample> samples, const DeviceSpec& spec = {});

  const DeviceSpec& spec() const override { return spec_; }
  bool open() override { return true; }
  void close() override {}
  DeviceReading read(double t) override;
  void sendForce(const Vec3& force) override { lastForce_ = force; ++forcesSent_; }
  const char* error() const override { return error_; }

  // Test hooks (same thread as the loop, or before it starts).
  void failWith(const char* message) { error_ = message; }
  void stallFrom(double t) { stallFrom_ = t; }
  const Vec3& lastForce() const { return lastForce_; }
  long forcesSent() const { return forcesSent_; }

 private:
  DeviceReading fromTable(double t) const;

  DeviceSpec spec_;
  PoseFunction pose_;
  std::vector<PoseSample> samples_;
  DeviceReading last_;
  Vec3 lastForce_ = Vec3::Zero();
  long forcesSent_ = 0;
  const char* error_ = nullptr;
  double stallFrom_ = 1e300;
};

}  // namespace hemiroll::haptics
