#pragma once
// One small interface for every device (scripted, simulated hand; later mouse,
// SDL joystick, UDP bridge, replay). The servo thread calls read() and
// sendForce() once per tick: implementations must not block, allocate or do
// I/O there (a bridge keeps its socket work on its own thread and hands over
// the latest sample without locks).

#include <cstdint>

#include "engine/haptics/DeviceSpec.h"
#include "engine/physics/StateLayout.h"

namespace hemiroll::haptics {

using physics::Vec3;

// One sample of the device in its own coordinates.
struct DeviceReading {
  Vec3 position = Vec3::Zero();  // [m]
  Vec3 velocity = Vec3::Zero();  // [m/s]
  std::uint32_t buttons = 0;     // bit i = button i pressed
  // True when this is a new sample since the previous read; a device that
  // stops delivering returns its last sample with fresh = false, and the
  // stale-data watchdog counts how long that lasts.
  bool fresh = true;
  // The first reading of a device switched in for another (the player taking
  // over from the autopilot): its step from the previous reading is no
  // motion, so the position-jump guard starts its window afresh here.
  bool newPath = false;
};

class HapticDevice {
 public:
  virtual ~HapticDevice() = default;

  virtual const DeviceSpec& spec() const = 0;
  // Outside the servo loop. False on failure, with error() saying why.
  virtual bool open() = 0;
  virtual void close() = 0;
  // t is the loop's time [s] (the simulation clock; scripted devices are
  // functions of it, real ones ignore it).
  virtual DeviceReading read(double t) = 0;
  // Device coordinates [N]; already clamped by the safety layer.
  virtual void sendForce(const Vec3& force) = 0;
  // Before each sendForce: the safety layer's fault this tick (0: none;
  // haptics::SafetyFault as a number), so that a device can tell its user
  // why the force is zero (the UDP bridge's status). Servo thread; must not
  // block or allocate.
  virtual void safetyState(std::uint8_t /*fault*/) {}
  // nullptr while healthy, else a static sentence (no allocation on report).
  virtual const char* error() const = 0;
  // Outside the servo loop: true once the device delivers samples, so that
  // a loop may start on it (a bridge waits for its client's first state;
  // its error() is brought up to date by read(), which a loop not yet
  // started does not call).
  virtual bool ready() const { return error() == nullptr; }
};

}  // namespace hemiroll::haptics
