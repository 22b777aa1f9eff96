#pragma once
// What a haptic device can do, in the CHAI3D manner: the loop and the safety
// layer read these limits and never exceed them.

namespace hemiroll::haptics {

struct DeviceSpec {
  const char* name = "device";   // for status lines and recordings (a string literal; never freed)
  double maxForce = 3.0;         // largest force the device may render [N]
  double maxStiffness = 1000.0;  // largest coupling stiffness it renders stably [N/m]
  double workspaceRadius = 0.1;  // radius of the reachable sphere about its origin [m]
  bool hasForceOutput = true;    // false for input-only devices (mouse): forces are shown, not felt
};

}  // namespace hemiroll::haptics
