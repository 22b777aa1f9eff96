#pragma once
// A haptic device's limits as its profile file declares them
// (devices/*.lua, docs/UDP_BRIDGE.md "Device profiles"), in plain C++. The
// game turns it into the device's haptics::DeviceSpec and the safety
// layer's limits (game/trial/DeviceProfiles.h); the script layer only reads it.

#include <optional>
#include <string>

namespace hemiroll::task {

struct DeviceProfileDef {
  std::string source;   // the file as named by the caller, for messages
  std::string name;     // the file's stem ("touch"): what a protocol, a setting or a flag names
  std::string model;    // "3D Systems Touch": what a sentence calls the device
  std::string maker;
  double peakForceN = 0.0;         // the clamp: no force longer than this is ever sent [N]
  double continuousForceN = 0.0;   // what it may hold indefinitely [N], <= peak
  double maxStiffnessNPerM = 0.0;  // the stiffest coupling it renders stably [N/m]
  std::optional<double> maxDampingNsPerM;  // unset: the maker publishes none, not checked
  // The reachable box, centred on the device's origin [m] (width x, depth y, height z).
  double workspaceWidthM = 0.0, workspaceDepthM = 0.0, workspaceHeightM = 0.0;
  double updateRateHz = 1000.0;    // the device's own servo rate [Hz]
  double positionResolutionM = 0.0;  // one count of its encoders at the workspace centre [m]; 0: unknown
  int forceAxes = 3;               // axes it pushes on
  int sensedAxes = 3;              // axes it measures (6 with a gimbal's rotations)
  // The project's choices, not the maker's (defaults below when absent):
  double maxForceRateNPerS = 200.0;      // the safety layer's rate limit [N/s]
  double aboveContinuousLimitS = 10.0;   // longest stretch above the continuous force before a stop [s]
  double workspaceMarginM = 0.01;        // how far outside the box a position may be before a stop [m]
};

}  // namespace hemiroll::task
