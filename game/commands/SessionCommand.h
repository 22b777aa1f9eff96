#pragma once
// `hemiroll session PROTOCOL.lua --participant ID [--bot BOT.lua] ...`: a
// research protocol run headless by a bot into a session folder, resumable
// (docs/PROTOCOLS.md). Exit codes: game/commands/ExitCode.h.

#include <string>
#include <vector>

namespace hemiroll::game {

int runSessionCommand(const std::vector<std::string>& args);

}  // namespace hemiroll::game
