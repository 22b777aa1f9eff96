#pragma once
// The flags of `hemiroll run`, parsed and checked before any file is read.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "game/trial/HumanBot.h"

namespace hemiroll::game {

struct RunOptions {
  std::string levelPath;
  std::string botPath;                     // --bot (required): a Lua file, or "autopilot"
  double autopilotBudget = 1.0;            // --autopilot-budget: planning effort, 0.25 .. 4
  std::uint64_t seed = 0;                  // --seed: 0 .. 2^63 - 1
  std::optional<std::string> recordDir;    // --record DIR
  bool realtime = false;                   // --realtime
  // --device-profile NAME|FILE: the device's limits (devices/NAME.lua): the
  // clamp, stiffness, rate limit and workspace the trial is held to.
  std::optional<std::string> deviceProfile;
  // --device bot|udp: who plays. "udp": a person at a real device behind the
  // UDP bridge on 127.0.0.1:--port (needs --realtime; no --bot).
  std::string device = "bot";
  int port = 47110;
  double clientTimeout = 30.0;             // --client-timeout [s] for the device's first state
  // --guidance KIND with --guidance-stiffness K [N/m] (a gain for error
  // augmentation) and --guidance-damping C [N s/m]: haptic guidance
  // towards (or away from) the autopilot's plan (docs/PROTOCOLS.md "Guidance").
  std::string guidance = "none";
  double guidanceStiffness = 200.0;
  std::optional<double> guidanceDamping;
  // --human-*: the human model's settings (HumanFlags.h).
  HumanBotOptions human;
  std::string humanDevice;
  bool help = false;                       // --help
};

struct RunOptionsResult {
  RunOptions options;
  std::string error;  // empty when the flags are good
};

// Parses the arguments after "run". Accepts "--flag value" and "--flag=value".
RunOptionsResult parseRunOptions(const std::vector<std::string>& args);

const char* runUsage();

}  // namespace hemiroll::game
