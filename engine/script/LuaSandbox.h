#pragma once
// One Lua 5.4 state that runs untrusted text under an allow-list environment,
// an instruction quota and a memory cap (see Script.h for what is allowed).
//
// Error discipline: every entry into Lua goes through lua_pcall (or the
// protected lua_load), so a Lua error never unwinds C++ frames; the error is
// turned into a ScriptError *after* the protected call has returned. The C
// functions this class installs (hook, print, setmetatable, message handler)
// hold no C++ objects while they may raise.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "engine/script/SandboxLimits.h"
#include "engine/script/TrialTiming.h"

struct lua_State;
struct lua_Debug;

namespace hemiroll::script {

class LuaSandbox {
 public:
  explicit LuaSandbox(const SandboxLimits& limits = {});
  ~LuaSandbox();
  LuaSandbox(const LuaSandbox&) = delete;
  LuaSandbox& operator=(const LuaSandbox&) = delete;

  // Compiles `source` (text only: precompiled bytecode is refused) as a chunk
  // whose name appears in messages ("rose.lua:3: ..."), runs it in the sandbox
  // environment under the chunk quota and leaves exactly `nresults` values on
  // the stack. Throws ScriptError ("name:line: message") on any failure.
  void runChunk(std::string_view source, const std::string& chunkName, int nresults);

  // Reads a file and runs it as runChunk does, named by `path` as given (a
  // byte-order mark and a '#' first line skipped: skipInterpreterPrefix).
  void runFile(const std::string& path, int nresults);

  // Calls the function lying below `nargs` arguments on top of the stack,
  // under the per-call quota; returns how many results it left (nresults may
  // be LUA_MULTRET, -1). `where` names the callee for errors that carry no
  // position of their own (memory): e.g. "tether.lua:12".
  int call(int nargs, int nresults, std::string_view where);
  // The same for a call made every tick (a bot's act, a level's
  // on_update): in real time it also has the tick's CPU budget
  // (setTickCpuLimit).
  int callPerTick(int nargs, int nresults, std::string_view where);

  // Time budgets a trial sets (TrialTiming.h). Real time: each per-tick call
  // may use this much CPU (0: none; its thread's CPU clock, read only once
  // the call has run that long by the wall clock). Headless: all calls of
  // the run together may spend limits().trialSeconds + trialSecondsPer...
  // per simulated second inside Lua; advanceRun(t) says how far the
  // simulation is. startRun resets the time spent.
  void setTickCpuLimit(double seconds) { tickCpuLimit_ = seconds; }
  // The budgets of a trial run as `timing` says: real time, the tick's CPU
  // per per-tick call; headless, a run starting now.
  void setTiming(const TrialTiming& timing);
  void startRun();
  void advanceRun(double simulatedSeconds) { simulatedSeconds_ = simulatedSeconds; }
  double runSecondsSpent() const { return runSpent_; }

  // Library calls (LuaLibraryBounds.h). Before a bounded function runs:
  // Run, or Refused when its worst case `worstSteps` is over what one call
  // may take here (nothing ran: an ordinary error), or LimitReached when a
  // time limit or, with `chargeSteps` added, the quota is spent (every
  // further instruction of this call fails too). `why` gets the sentence.
  enum class LibraryVerdict { Run, Refused, LimitReached };
  LibraryVerdict admitLibraryCall(const char* name, double worstSteps, double chargeSteps, const char* detail,
                                  char* why, std::size_t size);
  // After it ran: false when a time limit was reached meanwhile.
  bool libraryCallReturned(char* why, std::size_t size);
  // Makes every further instruction of the running call fail with
  // `message` (a limit was reached; a pcall must not swallow it), then
  // raises it.
  [[noreturn]] static void raiseLimit(lua_State* L, const char* message);

  lua_State* state() const { return L_; }
  // Pushes the scripts' environment table (_ENV of every chunk), for engine
  // services that add globals or load further chunks into the same sandbox.
  void pushEnvironment() const;
  const SandboxLimits& limits() const { return limits_; }
  // print()'s output budget: true while `bytes` more may be written (and
  // counts them); the first refusal is told once on stderr.
  bool spendPrintBudget(std::size_t bytes);
  // The sandbox that owns `L` (C functions installed in it find it so).
  static LuaSandbox& of(lua_State* L);
  std::size_t memoryInUse() const { return bytesInUse_; }
  // Instructions counted during the last protected call (in units of the
  // hook interval, so a multiple of it).
  std::uint64_t instructionsUsed() const { return instructionsUsed_; }

 private:
  static void* allocate(void* self, void* block, std::size_t oldSize, std::size_t newSize);
  static void countHook(lua_State* L, lua_Debug* ar);

  using Clock = std::chrono::steady_clock;

  void buildEnvironment();
  // Runs the function below nargs arguments with the limits armed; on failure
  // returns the complete message (status != LUA_OK) and clears the stack back.
  int protectedCall(int nargs, int nresults, std::uint64_t quota, double wallSeconds, double cpuSeconds,
                    std::string_view where, std::string& error);
  void arm(std::uint64_t quota, double wallSeconds, double cpuSeconds);
  void disarm();
  // False when a time limit is reached at `now` (`why` says which); moves
  // the next check to the earliest limit still ahead.
  bool timeAllows(Clock::time_point now, char* why, std::size_t size);
  void adaptHookInterval(lua_State* L, Clock::time_point now);

  SandboxLimits limits_;
  lua_State* L_ = nullptr;
  int environmentRef_ = 0;  // registry reference to the scripts' _ENV table

  // Memory: the cap applies only while script code runs (armed). Host-side
  // reads between calls may allocate freely, so that they can never raise a
  // Lua memory error outside a protected call.
  std::size_t bytesInUse_ = 0;
  bool armed_ = false;

  std::uint64_t instructionBudget_ = 0;
  std::uint64_t instructionsUsed_ = 0;
  double chargedSteps_ = 0.0;  // library work not yet whole instructions
  std::size_t bytesPrinted_ = 0;
  bool printCut_ = false;

  // Time, while a call runs. nextCheck_ is the earliest of the limits, so
  // that the hook's common case is one comparison.
  Clock::time_point armedAt_, wallDeadline_, runDeadline_, cpuCheck_, nextCheck_, lastHook_;
  double wallSeconds_ = 0.0;
  double cpuSeconds_ = 0.0;     // this call's CPU budget (0: none)
  double cpuStart_ = 0.0;       // the thread's CPU clock when armed [s]
  double stepCap_ = 0.0;        // what one library call may take now
  int hookInterval_ = 1000;
  bool limitReached_ = false;   // every further instruction raises limitMessage_
  char limitMessage_[512] = {};

  // The trial's budgets (TrialTiming).
  double tickCpuLimit_ = 0.0;
  bool runBudget_ = false;
  double runSpent_ = 0.0, simulatedSeconds_ = 0.0;
};

}  // namespace hemiroll::script
