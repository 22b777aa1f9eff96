#pragma once
// Why a trial at a device stopped, in words a lab technician acts on: what
// happened, in the device's terms, and what to check. One sentence per
// stop, for the results, the sidecar, the summary line and the HUD; the
// packet counts of the UDP bridge beside it.

#include <cstdint>
#include <string>

#include "engine/haptics/ForceSafety.h"
#include "engine/haptics/devices/UdpBridgeDevice.h"

namespace hemiroll::game {

// What the bridge knew when the safety layer stopped the force.
struct BridgeFacts {
  bool present = false;            // the device is behind the UDP bridge
  bool stale = false;              // the bridge's watchdog held (no good state within its time)
  bool clientGone = false;         // still silent well after the stop: the client has gone
  double silentFor = 0.0;          // [s] since the latest good state, when judged
  std::uint8_t deviceStatus = 0;   // the status byte of the client's latest fault report (0: none)
  double watchdog = 0.010;         // [s] the bridge's watchdog time
};

// The limits a stop is judged against, for the numbers in its sentence.
struct StopLimits {
  double continuousForce = 0.0;        // [N]
  double aboveContinuousLimit = 0.0;   // [s]
  double maxTickLateness = 0.020;      // [s]
  double staleLimit = 0.010;           // [s]
  double maxDeviceSpeed = 2.0;         // [m/s]
};

// The figures of a loop's safety definition that the sentences name.
StopLimits stopLimitsOf(const haptics::SafetyDef& safety);

// One sentence for a stop; "" for SafetyFault::None.
std::string deviceStopWords(haptics::SafetyFault fault, const BridgeFacts& bridge, const StopLimits& limits);

// "12345 device states received, 3 lost, 1 out of order, 2 late, 0 malformed"
std::string packetCountWords(const haptics::UdpBridgeCounters& c);

}  // namespace hemiroll::game
