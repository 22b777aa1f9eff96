#pragma once
// `hemiroll sim SCENARIO.lua [...]`: a pure physics run of a scenario file,
// CSV out (design.md, "Contracts"; docs/SCENARIOS.md).

#include <string>
#include <vector>

namespace hemiroll::game {

// Arguments after "sim". Returns the process exit code (ExitCode.h).
int runSimCommand(const std::vector<std::string>& args);

}  // namespace hemiroll::game
