#pragma once
// Devices by name (DeviceNames.h), for the command line, levels and settings:
//   "mouse"           MouseDevice          (the UI feeds it; no force output)
//   "mouse-hand"      MouseDevice          (the pointer pulls a simulated hand the force pushes)
//   "joystick"        SdlJoystickDevice    (SDL_Haptic constant force)
//   "udp"             UdpBridgeDevice      (a real device behind the bridge)
//   "scripted"        ScriptedDevice       (a pose function; holds still by default)
//   "simulated-hand"  SimulatedHandDevice  (spring-mass hand; holds still by default)
// Others register with add() (engine/record's "replay" does). make()
// constructs; open() is the caller's (or makeAndOpen()'s), on the thread
// that owns SDL for the joystick. Every failure is a sentence, never an
// exception or a null without a reason.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/haptics/devices/DeviceNames.h"
#include "engine/haptics/devices/MouseDevice.h"
#include "engine/haptics/devices/ScriptedDevice.h"
#include "engine/haptics/devices/SimulatedHandDevice.h"
#include "engine/haptics/devices/UdpBridgeDevice.h"
#include "engine/haptics/devices/sdl/SdlJoystickDevice.h"

namespace hemiroll::haptics {

// Settings for every kind; each maker reads only its own.
struct DeviceOptions {
  MouseDeviceDef mouse;
  HandSpringDef mouseHand;  // the hand of "mouse-hand"
  SdlJoystickDef joystick;
  UdpBridgeDef udp;
  ScriptedDevice::PoseFunction scriptedPose;              // empty: hold still at the origin
  DeviceSpec scriptedSpec{"scripted", 3.0, 1000.0, 0.1, true};
  SimulatedHandDevice::IntentFunction handIntent;         // empty: hold still at the origin
  HandModelDef hand;
  DeviceSpec handSpec{"simulated hand", 3.0, 1000.0, 0.1, true};
};

struct DeviceChoice {
  std::unique_ptr<HapticDevice> device;  // null exactly when error is set
  std::string error;
};

class DeviceFactory {
 public:
  using Maker = std::function<std::unique_ptr<HapticDevice>(const DeviceOptions&)>;

  DeviceFactory();  // the six built-in devices

  // A new name (or a replacement for an existing one).
  void add(const std::string& name, const std::string& description, Maker make);
  DeviceChoice make(const std::string& name, const DeviceOptions& options = {}) const;
  // make() then open(); the device's own error() sentence when open fails.
  DeviceChoice makeAndOpen(const std::string& name, const DeviceOptions& options = {}) const;

  // The spec a device of that name would have with these options, without
  // opening it (a replay of its trial clamps to the same limits); nullopt
  // for an unknown name.
  std::optional<DeviceSpec> specOf(const std::string& name, const DeviceOptions& options = {}) const;

  std::vector<std::string> names() const;
  // One line per device: name, description, and its spec with units.
  std::string describe(const DeviceOptions& options = {}) const;

 private:
  struct Entry {
    std::string name, description;
    Maker make;
  };
  std::vector<Entry> entries_;
};

// "maxForce 3 N, maxStiffness 1000 N/m, workspace radius 0.1 m, force output yes"
std::string describeSpec(const DeviceSpec& spec);

}  // namespace hemiroll::haptics
