#pragma once
// The reference client of the UDP bridge: a spring-mass hand
// (SimulatedHandDevice) on a simulated device (SimulatedDevice.h: handle
// mass and friction, the peak force, quantised positions, a network with
// jitter, loss and reordering) that sends its state to the bridge at a fixed
// rate on absolute deadlines and applies every force that comes back
// (zero-order hold until the next one). Between sends it waits in ppoll on the socket,
// so it sleeps instead of spinning. Also what a client for a real device
// looks like (docs/UDP_BRIDGE.md).

#include <atomic>
#include <cstdint>
#include <ostream>
#include <string>

#include "tools/hapticclient/ClientOptions.h"

namespace hemiroll::hapticclient {

struct ClientSummary {
  std::uint64_t statesSent = 0;
  std::uint64_t lateSends = 0;        // sends more than one period behind their deadline
  std::uint64_t forcesReceived = 0;   // good force datagrams
  std::uint64_t forcesMalformed = 0;
  std::uint64_t forcesOutOfOrder = 0; // bridge sequence not after the previous one
  std::uint64_t forcesLost = 0;       // gaps in the bridge's sequence
  std::uint64_t statesAnswered = 0;   // distinct states that got a force
  std::uint64_t staleForces = 0;      // forces with status Stale
  std::uint64_t safetyStops = 0;      // forces with status SafetyStop
  int lastSafetyFault = 0;            // the last one's fault (haptics::SafetyFault as a number)
  bool bridgeClosed = false;          // a Closing status arrived
  double maxForce = 0.0;              // largest |F| rendered: received, after the device's clamp (--peak-force) [N]
  // Round trip: from sending a state to receiving the first force computed
  // from it [s]; includes the wait for the bridge's next servo tick.
  double rttMin = 0.0, rttMedian = 0.0, rttP99 = 0.0, rttMax = 0.0;
  // The simulated link's own books (--loss, --reorder) and the step
  // response (--step): from sending the first state after an edge to the
  // first force that answers it and differs by more than 0.02 N [s].
  std::uint64_t statesDropped = 0, statesReordered = 0;
  // Of those dropped, the ones between the first and the last state the
  // bridge answered: the drops the bridge could see as gaps (not those
  // before it heard the client or after it stopped listening).
  std::uint64_t statesDroppedWhileAnswered = 0;
  std::uint64_t steps = 0;
  double stepMedian = 0.0, stepP10 = 0.0, stepP90 = 0.0, stepMax = 0.0;
  bool exited = false;                // left at --exit-at
  bool realtime = false;              // SCHED_FIFO was granted
  std::string error;                  // set when the client could not run
};

// Runs until options.duration has passed or stop becomes true.
ClientSummary runClient(const ClientOptions& options, const std::atomic<bool>& stop);

// "key value" lines, one per figure, for people and for tests.
void printSummary(const ClientSummary& s, std::ostream& out);

}  // namespace hemiroll::hapticclient
