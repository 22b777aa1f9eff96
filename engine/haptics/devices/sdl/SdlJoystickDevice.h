#pragma once
// A force-feedback joystick or wheel through SDL2 (SDL_Joystick + SDL_Haptic):
// the stick's axes give the pose (JoystickMapping: dead zone, reach), and
// the force goes out as one constant-force effect whose level and direction
// are updated as the force changes (JoystickMapping: level 32767 = maxForce).
//
// Threads, and which SDL calls happen on which:
//   - open() and close(): on the thread that owns SDL (the main thread, the
//     one that calls SDL_Init and pumps events). They call
//     SDL_InitSubSystem/SDL_QuitSubSystem, SDL_JoystickOpen/Close,
//     SDL_HapticOpenFromJoystick/Close, SDL_HapticNewEffect/RunEffect/
//     DestroyEffect. open() starts, close() joins the device thread.
//   - the device thread (ours, 1 kHz on absolute deadlines): SDL_JoystickUpdate,
//     SDL_JoystickGetAxis/GetButton/GetAttached, SDL_HapticUpdateEffect.
//     SDL serialises joystick access with its own joystick lock, so this may
//     run beside the main thread's event pump (which then also sees the
//     axis events: harmless). A program with no event pump should call
//     SDL_JoystickEventState(SDL_IGNORE) so that those events do not pile up.
//   - the servo thread: read() and sendForce() call no SDL at all (SDL's
//     joystick lock is shared with the UI thread, and a USB write may block),
//     they only swap TripleBuffers with the device thread.
// A joystick unplugged mid-run makes error() say so (DeviceError: force off
// at once, play paused); a device thread that stops delivering trips the
// safety layer's stale-data watchdog.

#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

#include "engine/haptics/HapticDevice.h"
#include "engine/haptics/JoystickMapping.h"
#include "engine/haptics/MonotonicClock.h"
#include "engine/haptics/TripleBuffer.h"
#include "engine/haptics/VelocityEstimator.h"

struct _SDL_Joystick;  // SDL's own opaque types (SDL_Joystick, SDL_Haptic): no SDL header here
struct _SDL_Haptic;

namespace hemiroll::haptics {

struct SdlJoystickDef {
  int index = 0;                      // SDL device index (0 = the first joystick)
  JoystickMappingDef mapping;
  VelocityFilterDef velocity;
  bool requireForceFeedback = true;   // false: a joystick without SDL_Haptic works as input only
  // With requireForceFeedback: a stick without SDL_Haptic is still taken
  // (input only) when it can rumble (a gamepad): rumble() then stands in
  // for the force it cannot render.
  bool acceptRumble = false;
  double updateRate = 1000.0;         // device thread: axis polls and effect updates per second [Hz]
  // SDL levels are relative; maxForce is the force [N] that full level stands
  // for, a nominal figure for desktop force-feedback sticks (1-3 N at the
  // grip). Their motors are slow, so the coupling stiffness stays modest.
  // The workspace radius is the mapping's reach.
  DeviceSpec spec{"sdl joystick", 2.0, 300.0, 0.05, true};
};

class SdlJoystickDevice final : public HapticDevice {
 public:
  explicit SdlJoystickDevice(const SdlJoystickDef& def = {});
  ~SdlJoystickDevice() override;

  // spec().hasForceOutput is false after open() for an input-only joystick.
  const DeviceSpec& spec() const override { return spec_; }
  bool open() override;
  void close() override;
  DeviceReading read(double t) override;
  void sendForce(const Vec3& force) override;
  const char* error() const override;

  const std::string& joystickName() const { return name_; }
  // The thread that owns SDL (the UI's), after open(): rumble the stick's
  // motors at `strength` in [0, 1] for the next 150 ms (call it every frame
  // to keep it going; 0 stops it). False when the stick has no rumble.
  // SDL's joystick lock serialises it with the device thread.
  bool rumble(double strength);

 private:
  struct Pose {
    std::array<double, 3> position{};
    std::uint32_t buttons = 0;
    std::uint64_t serial = 0;
    bool attached = true;
  };
  struct ForceSample {
    std::array<double, 3> force{};
  };
  enum class Health { NotOpen, Starting, Ok, Disconnected };

  bool fail(std::string message);
  void run();

  SdlJoystickDef def_;
  DeviceSpec spec_;
  std::string openError_, disconnectedError_, name_;
  _SDL_Joystick* joystick_ = nullptr;
  _SDL_Haptic* haptic_ = nullptr;
  int effect_ = -1;
  bool subsystems_ = false;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> firstPose_{false};  // set by the device thread; open() waits for it
  TripleBuffer<Pose> poses_;          // device thread -> servo thread
  TripleBuffer<ForceSample> forces_;  // servo thread -> device thread
  // Servo thread only.
  Pose current_;
  std::uint64_t lastSerial_ = 0;
  VelocityEstimator velocity_;
  std::atomic<Health> health_{Health::NotOpen};
};

}  // namespace hemiroll::haptics
