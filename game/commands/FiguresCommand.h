#pragma once
// `hemiroll figures --out DIR [--scenario FILE]`: the paper's Figs. 9, 10
// and 11 regenerated from the simulator (the prescribed rose drive of
// levels/scenarios/rose_paper.lua, 35 s, RK4 at 1 ms), with the features
// the analysis measures on that run (docs/FIGURES.md).

#include <string>
#include <vector>

namespace hemiroll::game {

// Arguments after "figures". Returns the process exit code (ExitCode.h).
int runFiguresCommand(const std::vector<std::string>& args);

}  // namespace hemiroll::game
