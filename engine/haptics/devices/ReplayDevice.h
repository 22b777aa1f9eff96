#pragma once
// Plays back a logged sequence of device readings, one per read(): the k-th
// read returns exactly the k-th logged TickInput, so a ServoLoop built with
// the same definition reproduces the logged run bit for bit (forces sent are
// ignored: the log already contains the hand's answer to them). Reading the
// log from disk is engine/record's job (ReplayReader); this device only
// holds the samples, so the servo thread never touches a file.
//
// After the last sample the device reports an error ("replay log ended") and
// repeats the last pose as stale, so the safety layer takes the force off.

#include <cstddef>
#include <vector>

#include "engine/haptics/HapticDevice.h"
#include "engine/haptics/RecordRow.h"

namespace hemiroll::haptics {

class ReplayDevice final : public HapticDevice {
 public:
  explicit ReplayDevice(std::vector<TickInput> inputs, const DeviceSpec& spec = {});

  const DeviceSpec& spec() const override { return spec_; }
  bool open() override { return true; }
  void close() override {}
  DeviceReading read(double t) override;
  void sendForce(const Vec3& force) override { lastForce_ = force; }
  const char* error() const override { return error_; }

  std::size_t position() const { return next_; }  // samples played so far
  std::size_t size() const { return inputs_.size(); }
  bool finished() const { return next_ >= inputs_.size(); }
  const Vec3& lastForce() const { return lastForce_; }

 private:
  std::vector<TickInput> inputs_;
  DeviceSpec spec_;
  std::size_t next_ = 0;
  DeviceReading last_;
  Vec3 lastForce_ = Vec3::Zero();
  const char* error_ = nullptr;
};

}  // namespace hemiroll::haptics
