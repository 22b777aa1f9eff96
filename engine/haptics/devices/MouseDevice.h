#pragma once
// The mouse as a device: the proxy follows the pointer on a horizontal plane,
// the wheel sets its height (PointerMapping does pixels -> metres on the UI
// side). A mouse renders no force (spec.hasForceOutput = false): the renderer
// shows the coupling force as an arrow instead.
//
// Threads: the UI thread (the one with the window and its events) calls
// setPointer(); the servo thread calls read(). They meet only in a
// TripleBuffer (lock free, wait free), so the servo tick never waits for the
// UI. No SDL here: the UI translates its events.
//
// Velocity: VelocityEstimator (finite difference between pointer samples,
// clamped to 1 m/s, low-pass 20 ms) on the device's monotonic clock, not on
// the loop's simulation time, which stops while play is paused. A pointer
// standing still is a valid pose, so every read is fresh once a position has
// arrived (nothing to go stale: there is no force to hold).
//
// The "hand" feel (issue 26; the factory's "mouse-hand"): the proxy is not
// the pointer but a simulated hand (HandSpring) that the pointer pulls
// through a spring and the coupling force pushes, as a real device pushes the
// hand holding it; the physics is the same, only the hand is simulated. The
// device then renders force - to that hand - so its spec says so and the
// safety layer clamps and ramps what it gets (kMouseHandSpec). The hand runs
// in read() on the device's monotonic clock (it follows the pointer while
// the physics stands still too), from the force of the previous tick.

#include <array>
#include <atomic>
#include <cstdint>

#include "engine/haptics/HandSpring.h"
#include "engine/haptics/HapticDevice.h"
#include "engine/haptics/MonotonicClock.h"
#include "engine/haptics/TripleBuffer.h"
#include "engine/haptics/VelocityEstimator.h"

namespace hemiroll::haptics {

struct MouseDeviceDef {
  VelocityFilterDef velocity;
  MonotonicClock clock = &monotonicNowNs;
  // maxForce 0: nothing is rendered. maxStiffness is not used without force
  // output; workspaceRadius matches PointerMappingDef's default reach.
  DeviceSpec spec{"mouse", 0.0, 1000.0, 0.1, false};
  // The hand feel: the proxy is this simulated hand (mouseHandDef sets it).
  bool hand = false;
  HandSpringDef handSpring;
};

// The hand feel's spec: it renders force to the simulated hand, at most a
// desk device's 3 N (DeviceSpec's default, the bots' too, so that the human
// model's measurements and the window clamp alike).
inline constexpr DeviceSpec kMouseHandSpec{"mouse-hand", 3.0, 1000.0, 0.1, true};
// `base` with the hand feel on (its spec kMouseHandSpec).
MouseDeviceDef mouseHandDef(const MouseDeviceDef& base = {}, const HandSpringDef& hand = {});

class MouseDevice final : public HapticDevice {
 public:
  // Throws std::invalid_argument naming the field for a bad hand.
  explicit MouseDevice(const MouseDeviceDef& def = {});

  const DeviceSpec& spec() const override { return def_.spec; }
  bool open() override { return true; }
  void close() override {}
  DeviceReading read(double t) override;
  void sendForce(const Vec3& force) override { lastForce_ = force; }
  const char* error() const override { return nullptr; }

  // UI thread. position [m] in device coordinates (PointerMapping::toMetres);
  // jump = the pointer did not travel here (it entered the window, or was
  // warped): the velocity restarts from zero instead of seeing a fling.
  void setPointer(const Vec3& position, std::uint32_t buttons = 0, bool jump = false);

  const Vec3& lastForce() const { return lastForce_; }  // servo thread: what the arrow would show

 private:
  struct PointerSample {
    std::array<double, 3> position{};
    std::uint32_t buttons = 0;
    std::uint64_t serial = 0;  // +1 per setPointer
    std::uint64_t jumps = 0;   // +1 per jump; a change resets the velocity
  };

  MouseDeviceDef def_;
  TripleBuffer<PointerSample> pointer_;
  // UI thread only.
  std::uint64_t serial_ = 0, jumps_ = 0;
  // Servo thread only.
  PointerSample current_;
  std::uint64_t lastSerial_ = 0, lastJumps_ = 0;
  VelocityEstimator velocity_;
  Vec3 lastForce_ = Vec3::Zero();
  HandSpring hand_;
  double handTime_ = -1.0;  // the clock's time of the hand's last step [s]; < 0: not placed yet
};

}  // namespace hemiroll::haptics
