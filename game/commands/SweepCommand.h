#pragma once
// `hemiroll sweep`: parameter sweeps of the paper's rose drive, their shards'
// merge and their maps (docs/SWEEP.md).
//   hemiroll sweep SPEC.lua --out DIR [--threads N] [--shard i/N] [--maps svg|none]
//   hemiroll sweep merge DIR... --out DIR [--maps svg|none]
//   hemiroll sweep map DIR --x PARAM --y PARAM --metric NAME [--aggregate HOW] [--out FILE.svg]

#include <string>
#include <vector>

namespace hemiroll::game {

// Arguments after "sweep". Returns the process exit code (ExitCode.h).
int runSweepCommand(const std::vector<std::string>& args);

}  // namespace hemiroll::game
