#pragma once
// The flags of `hemiroll session`, parsed and checked before any file is read.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "game/trial/HumanBot.h"

namespace hemiroll::game {

struct SessionOptions {
  std::string protocolPath;
  std::string participant;                 // --participant (required)
  std::string session = "1";               // --session
  std::optional<std::string> dataRoot;     // --data DIR (default: the game's data directory/sessions)
  std::optional<std::string> botPath;      // --bot: without it, people play in the game window
  std::optional<std::uint64_t> seed;       // --seed: 0 .. 2^63 - 1 (default: the protocol's)
  std::optional<std::string> deviceProfile;  // --device-profile: the device's limits (else the protocol's)
  // --device udp: a participant at a real device behind the UDP bridge
  // plays every trial (no window); --port, --client-timeout as for `run`.
  std::string device = "bot";
  int port = 47110;
  double clientTimeout = 30.0;
  std::string levelsDir;                   // --levels DIR ("" = the folder named levels above the protocol)
  // --participants N: a cohort of N simulated participants, <ID>-01 ..
  // <ID>-N (ID: --participant, default "sim"), one after the other, each
  // with the plan's seed plus its number less one.
  int participants = 0;                    // 0: one participant (--participant)
  HumanBotOptions human;                   // --human-* (HumanFlags.h)
  bool help = false;
};

struct SessionOptionsResult {
  SessionOptions options;
  std::string error;  // empty when the flags are good
};

SessionOptionsResult parseSessionOptions(const std::vector<std::string>& args);

const char* sessionUsage();

}  // namespace hemiroll::game
