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
  // Library functions that loop or allocate inside C (string.rep,
  // table.move, the pattern functions, ...) run where no hook does: one
  // call's worst case is worked out before it runs and the call refused when
  // it exceeds this many steps (LuaLibraryBounds.h; a step is a character
  // scanned, compared or copied, an element moved, a class tested). s:find
  // of "%b()" on 14 000 unbalanced characters is 2e8 steps and 0.13 s.
  double libraryStepBound = 2e8;
  // ... or what the call's own time limit allows at this many steps a
  // second (a real-time tick's 2 ms: 2e5), so that no single library call
  // outlasts its budget by more than it.
  double libraryStepsPerSecond = 1e8;
  // The part of a library call's work that is certain (the bytes it reads
  // and writes, the elements it moves) is charged to the instruction quota
  // at this many steps an instruction: a loop of large calls meets the
  // quota as a loop of instructions does (a VM instruction takes about as
  // long as 16 bytes decoded or compared).
  double libraryStepsPerInstruction = 16.0;
  // A trial run headless (bit-for-bit, no clock in the loop) lets each of
  // its scripts (the bot's, the level's) spend this long inside Lua in all,
  // plus this much per simulated second (docs/RUN.md); past it the trial
  // ends with the reason. In real time each tick's call has the tick's
  // deadline instead (TrialTiming).
  double trialSeconds = 2.0;
  double trialSecondsPerSimulatedSecond = 1.0;
  // What print() may write to stderr over the sandbox's life [bytes]; then
  // one line says so and the rest is dropped (a bot printing every tick
  // wrote 19.8 GB in a minute).
  std::size_t printBudgetBytes = std::size_t{1} << 20;
};

}  // namespace hemiroll::script
