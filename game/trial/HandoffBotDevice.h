#pragma once
// The device a bot holds in real-time play (`hemiroll run --realtime`): the
// bot runs on the main thread at its own rate, never in the servo thread.
// Each answer is published with the simulation time of the observation it
// answers, through a TripleBuffer (lock free, wait free, latest wins); the
// servo thread reads the latest on every tick and extrapolates it linearly
// to the tick's time, so the proxy moves smoothly between the bot's samples
// instead of stepping at the bot's rate. Extrapolation stops after
// maxExtrapolation (the pose is then held), and a sample older than
// staleAfter is delivered as not fresh, so the loop's stale-data watchdog
// stops a bot that stopped answering. Poses go through the same mapping and
// workspace stop as BotDevice.

#include <array>

#include "engine/haptics/HapticDevice.h"
#include "engine/haptics/TripleBuffer.h"
#include "engine/haptics/WorkspaceMapping.h"

namespace hemiroll::game {

using haptics::Vec3;

class HandoffBotDevice final : public haptics::HapticDevice {
 public:
  static constexpr double kMaxExtrapolation = 0.02;  // [s] of simulation time, 10 bot periods at 500 Hz
  static constexpr double kStaleAfter = 0.05;        // [s]; with the 10 ms watchdog a bot 60 ms late stops the trial

  HandoffBotDevice(const haptics::DeviceSpec& spec, const haptics::WorkspaceMapping& mapping);

  const haptics::DeviceSpec& spec() const override { return spec_; }
  bool open() override { return true; }
  void close() override {}
  // Servo thread.
  haptics::DeviceReading read(double t) override;
  void sendForce(const Vec3&) override {}  // a bot feels nothing
  const char* error() const override { return nullptr; }

  // Main thread. `simTime` is the time of the observation answered [s].
  // Without a velocity, the difference to the previous published pose.
  void publish(double simTime, const Vec3& scenePosition);
  void publish(double simTime, const Vec3& scenePosition, const Vec3& sceneVelocity);

 private:
  struct Sample {
    double time = 0.0;
    std::array<double, 3> position{}, velocity{};  // device coordinates [m], [m/s]
  };
  void send(double simTime, const Vec3& devicePosition, const Vec3& deviceVelocity);

  haptics::DeviceSpec spec_;
  haptics::WorkspaceMapping mapping_;
  haptics::TripleBuffer<Sample> samples_;
  // Main thread only.
  bool hasPrevious_ = false;
  Sample previous_;
};

}  // namespace hemiroll::game
