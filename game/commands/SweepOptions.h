#pragma once
// The flags of `hemiroll sweep`, `hemiroll sweep merge` and `hemiroll sweep
// map` (docs/SWEEP.md), parsed and checked before any file is read.

#include <optional>
#include <string>
#include <vector>

#include "game/research/sweep/SbatchDirectives.h"
#include "game/research/sweep/SweepMetrics.h"
#include "game/research/sweep/SweepShard.h"

namespace hemiroll::game {

enum class SweepAction { Run, Merge, Map };

struct SweepOptions {
  SweepAction action = SweepAction::Run;
  bool help = false;
  // run: SPEC.lua; merge: the part folders; map: the sweep's folder.
  std::vector<std::string> inputs;
  std::optional<std::string> out;   // run, merge: the folder; map: the SVG file
  int threads = 0;                  // run: 0 = every CPU the process may use (OrderedPool::defaultThreads)
  int lanes = 0;                    // run: --lanes W, SIMD lanes per thread; 0 = the widest this CPU runs
  SweepShard shard;                 // run: --shard i/N
  int slurmTasks = 0;               // run: --slurm N writes a Slurm job of N shards instead of running (0: run)
  SlurmResources slurm;             // run with --slurm: --slurm-time, --slurm-partition, --slurm-account, --slurm-mem
  bool maps = true;                 // run (whole sweeps), merge: --maps svg|none
  // map:
  std::optional<std::string> x, y, metric;
  std::optional<Aggregate> aggregate;
};

struct SweepOptionsResult {
  SweepOptions options;
  std::string error;  // empty when the flags are good
};

// The arguments after "sweep": "merge ..." and "map ..." select those actions.
SweepOptionsResult parseSweepOptions(const std::vector<std::string>& args);

const char* sweepUsage();

}  // namespace hemiroll::game
