#pragma once
// The device a bot holds: the trial loop sets its pose between servo ticks
// (scene frame, as the bot gives it) and the servo loop reads it on the next
// tick, as it would read a hand on a real device. It behaves like hardware:
// the pose is mapped back to device coordinates through the level's
// workspace mapping and held inside the device's reachable sphere (a hand
// cannot push a stylus past its stops), and a velocity the bot does not give
// is the backward difference of successive poses, so position and velocity
// agree. Forces sent are kept for observation; nothing is rendered.
//
// Single-threaded: set and read on the loop's thread (headless play).

#include "engine/haptics/HapticDevice.h"
#include "engine/haptics/WorkspaceMapping.h"

namespace hemiroll::game {

using haptics::Vec3;

class BotDevice final : public haptics::HapticDevice {
 public:
  BotDevice(const haptics::DeviceSpec& spec, const haptics::WorkspaceMapping& mapping, double tickPeriod);

  const haptics::DeviceSpec& spec() const override { return spec_; }
  bool open() override { return true; }
  void close() override {}
  haptics::DeviceReading read(double t) override;
  void sendForce(const Vec3& force) override { lastForce_ = force; }
  const char* error() const override { return nullptr; }

  // Scene-frame pose for the next tick. Without a velocity, the device
  // derives one from the previous pose (zero on the first).
  void setPose(const Vec3& scenePosition);
  void setPose(const Vec3& scenePosition, const Vec3& sceneVelocity);

  // Scene -> device coordinates for a device of `spec` under `mapping`,
  // stopped at the workspace sphere (`limited` says whether it was).
  static Vec3 toDevice(const Vec3& scenePosition, const haptics::WorkspaceMapping& mapping,
                       const haptics::DeviceSpec& spec, bool& limited);

  // The pose the device actually delivers, back in the scene (after the stop).
  Vec3 scenePosition() const { return mapping_.positionToScene(reading_.position); }
  const Vec3& lastForce() const { return lastForce_; }  // device frame [N]
  bool limited() const { return limited_; }             // the last pose was outside the workspace

 private:
  haptics::DeviceSpec spec_;
  haptics::WorkspaceMapping mapping_;
  double period_;
  haptics::DeviceReading reading_;
  bool hasPose_ = false;
  bool limited_ = false;
  Vec3 lastForce_ = Vec3::Zero();
};

}  // namespace hemiroll::game
