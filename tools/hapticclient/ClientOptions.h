#pragma once
// Command-line options of hemiroll-haptic-client, the UDP bridge's reference
// client: where the bridge is, how long and how fast to send, and the hand
// model it emulates (engine/haptics/devices/SimulatedHandDevice).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/haptics/devices/SimulatedHandDevice.h"

namespace hemiroll::hapticclient {

struct ClientOptions {
  std::string host = "127.0.0.1";
  std::uint16_t port = 47110;
  double duration = 5.0;         // [s]; the client stops earlier on SIGINT/SIGTERM
  double rate = 1000.0;          // states per second [Hz]
  haptics::HandModelDef hand;    // mass [kg], stiffness [N/m], damping [N s/m]
  // The hand's intent: a circle in the horizontal plane that starts at centre,
  // p(t) = centre + r (sin wt, 1 - cos wt, 0), w = 2 pi f. r = 0 holds still.
  // The default is on the mass point of a level's default body (R = 4 cm,
  // upright), where the coupling engages; a hand elsewhere leaves it armed.
  std::array<double, 3> centre{0.0, 0.0, 0.04};  // device frame [m]
  double circleRadius = 0.0;     // [m]
  double circleFrequency = 0.5;  // [Hz]
  int realtimePriority = 0;      // SCHED_FIFO priority when permitted, 0: the normal scheduler
  // A simulated physical device between the hand and the wire
  // (docs/UDP_BRIDGE.md "A simulated device"): give it a profile's figures.
  double peakForce = 0.0;        // --peak-force: the motors' limit [N]; larger forces are clamped (0: none)
  double handleMass = 0.0;       // --handle-mass: the handle's moving mass, added to the hand's [kg]
  double friction = 0.0;         // --friction: the handle's Coulomb friction [N]
  double resolution = 0.0;       // --resolution: position quantisation, one encoder count [m] (0: none)
  // Network faults, drawn from --seed: each state delayed by a uniform
  // U(0, jitter), lost with probability `loss`, or held back and sent after
  // the next one with probability `reorder`.
  double jitter = 0.0;           // [s]
  double loss = 0.0;             // [0, 1]
  double reorder = 0.0;          // [0, 1]
  std::uint64_t seed = 1;
  // Scripted faults (negative: never): no state for pauseFor seconds from
  // pauseAt; leave for good at exitAt; report a device fault (status 1) from faultAt.
  double pauseAt = -1.0, pauseFor = 0.0;  // [s]
  double exitAt = -1.0;          // [s]
  double faultAt = -1.0;         // [s]
  // A square wave of +-step/2 on the reported x every stepPeriod/2 (0: none):
  // the summary gives the latency from each edge to the force's response.
  double step = 0.0;             // [m]
  double stepPeriod = 0.2;       // [s]
  bool help = false;
};

struct ParsedOptions {
  ClientOptions options;
  std::string error;  // empty when the command line was valid
};

ParsedOptions parseClientOptions(const std::vector<std::string>& args);
const char* clientUsage();

}  // namespace hemiroll::hapticclient
