#pragma once
// `hemiroll analyze RECORDING... [--out DIR] [--plots svg|none]`: the
// movement features of each trial (docs/ANALYSIS.md), a table over all of
// them, and plots.

#include <string>
#include <vector>

namespace hemiroll::game {

// Arguments after "analyze". Returns the process exit code (ExitCode.h).
int runAnalyzeCommand(const std::vector<std::string>& args);

}  // namespace hemiroll::game
