#pragma once
// Command-line options of hemiroll-haptic-client, the UDP bridge's reference
// client: where the bridge is, how long and how fast to send, and the hand
// model it emulates (engine/haptics/SimulatedHandDevice).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/haptics/SimulatedHandDevice.h"

namespace hemiroll::hapticclient {

struct ClientOptions {
  std::string host = "127.0.0.1";
  std::uint16_t port = 47110;
  double duration = 5.0;         // [s]; the client stops earlier on SIGINT/SIGTERM
  double rate = 1000.0;          // states per second [Hz]
  haptics::HandModelDef hand;    // mass [kg], stiffness [N/m], damping [N s/m]
  // The hand's intent: a circle in the horizontal plane that starts at centre,
  // p(t) = centre + r (sin wt, 1 - cos wt, 0), w = 2 pi f. r = 0 holds still.
  std::array<double, 3> centre{0.0, 0.0, 0.0};  // device frame [m]
  double circleRadius = 0.0;     // [m]
  double circleFrequency = 0.5;  // [Hz]
  int realtimePriority = 0;      // SCHED_FIFO priority when permitted, 0: the normal scheduler
  bool help = false;
};

struct ParsedOptions {
  ClientOptions options;
  std::string error;  // empty when the command line was valid
};

ParsedOptions parseClientOptions(const std::vector<std::string>& args);
const char* clientUsage();

}  // namespace hemiroll::hapticclient
