#pragma once
// `hemiroll run LEVEL.lua --bot BOT.lua [...]`: one headless (or paced) trial
// of a level played by a bot, one JSON line out (docs/RUN.md).

#include <string>
#include <vector>

namespace hemiroll::game {

// Arguments after "run". Returns the process exit code (ExitCode.h).
int runRunCommand(const std::vector<std::string>& args);

}  // namespace hemiroll::game
