#pragma once
// Budgets for untrusted Lua. A script that exceeds one is stopped with an
// error that says which budget ran out; nothing in the host is harmed.

#include <cstddef>
#include <cstdint>

namespace hemiroll::script {

struct SandboxLimits {
  // Lua VM instructions for running a whole chunk (a scenario file's top level).
  // Generous for data, small enough that `while true do end` fails in well
  // under a second.
  std::uint64_t chunkInstructionQuota = 20'000'000;
  // Lua VM instructions for one call from the host into a script function
  // (e.g. a proxy trajectory evaluated at every integrator stage).
  std::uint64_t callInstructionQuota = 1'000'000;
  // All memory the Lua state may hold while a script runs [bytes].
  std::size_t memoryLimitBytes = std::size_t{64} << 20;
  // Wall-clock time for a chunk and for one call [s]: a second guard behind
  // the instruction quotas, far above what they take (20 M instructions of
  // `while true` ran out in 0.11 s on this project's machine: about 100x
  // for a chunk, 400x for a call).
  double chunkWallSeconds = 10.0;
  double callWallSeconds = 2.0;
  // The string library's pattern functions (find, match, gmatch, gsub) may
  // backtrack for as long as they like inside C, where no hook runs: a
  // pattern whose worst case on its subject exceeds this many matcher steps
  // is refused before it runs (LuaPatternBound.h).
  double patternStepBound = 2e8;
  // What print() may write to stderr over the sandbox's life [bytes]; then
  // one line says so and the rest is dropped (a bot printing every tick
  // wrote 19.8 GB in a minute).
  std::size_t printBudgetBytes = std::size_t{1} << 20;
};

}  // namespace hemiroll::script
