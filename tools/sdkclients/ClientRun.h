#pragma once
// The order every SDK client keeps, whatever its device (UDP_BRIDGE.md,
// "Clients for device SDKs"):
//   start-up   open the device, open the link to the bridge, start the
//              device's servo loop with forces off, and turn forces on only
//              once the bridge has answered with an ok force, so that a
//              device never pushes before hemiroll is ready;
//   shut-down  (stop asked, the bridge closing, or the device failing) the
//              force to zero, forces off, the servo loop stopped, the device
//              closed: in that order, from whichever step was reached.

#include <atomic>
#include <cstdint>
#include <string>

#include "tools/sdkclients/BridgeLink.h"
#include "tools/sdkclients/DeviceDriver.h"

namespace hemiroll::sdkclients {

struct ClientRunDef {
  BridgeLinkDef link;          // its axes come from the driver; its force limit is lowered to the SDK's
  double duration = 0.0;       // [s]; 0 runs until stop or the bridge closes
  std::int64_t pollNs = 10'000'000;  // how often the supervising thread looks
};

struct ClientRunResult {
  std::string error;           // why it could not start, or why it stopped early
  LinkCounters counters;
  bool forcesWereEnabled = false;
  double forceLimit = 0.0;     // the limit the link applied [N]
};

// Runs the driver against the bridge until def.duration passes, stop turns
// true, or the bridge closes.
ClientRunResult runDeviceClient(DeviceDriver& driver, ClientRunDef def, const std::atomic<bool>& stop);

}  // namespace hemiroll::sdkclients
