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

  void buildEnvironment();
  // Runs the function below nargs arguments with the limits armed; on failure
  // returns the complete message (status != LUA_OK) and clears the stack back.
  int protectedCall(int nargs, int nresults, std::uint64_t quota, double wallSeconds, std::string_view where,
                    std::string& error);
  void arm(std::uint64_t quota, double wallSeconds);
  void disarm();

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
  std::chrono::steady_clock::time_point deadline_;
  std::size_t bytesPrinted_ = 0;
  bool printCut_ = false;
  double wallSeconds_ = 0.0;
};

}  // namespace hemiroll::script
