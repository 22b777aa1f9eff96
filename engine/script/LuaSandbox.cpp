#include "engine/script/LuaSandbox.h"

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <lua.hpp>
#include <sstream>

#include "engine/script/LuaLibraryBounds.h"
#include "engine/script/ScriptError.h"
#include "engine/script/ScriptSourceFile.h"

namespace hemiroll::script {

namespace {

// The count hook runs every this many VM instructions: cheap enough to leave
// on for every call, fine-grained enough that the quota overshoots by < 0.1%.
// Where instructions are slow (a comparison of two 30 MB strings is one),
// the hook comes more often, down to every instruction, so that the clock
// is read at least about every millisecond (adaptHookInterval).
constexpr int kHookInterval = 1000;
constexpr auto kHookTarget = std::chrono::milliseconds(1);
// A call starts with the hook this close, so that a call whose very first
// instructions are slow is checked after a hundred of them, not a thousand;
// the first hook of ordinary code widens it to kHookInterval.
constexpr int kFirstHookInterval = 100;

// The calling thread's CPU clock [s]: a system call (about 0.25 us), so it
// is read only when a CPU budget could have run out.
double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// ---- C functions that run inside Lua. They must hold no C++ objects with
// destructors, because any Lua API call in them may raise (longjmp).

// print() writes to stderr: stdout may carry the CSV of a run.
int sandboxPrint(lua_State* L) {
  const int n = lua_gettop(L);
  luaL_checkstack(L, n, "too many arguments to print");
  for (int i = 1; i <= n; ++i) luaL_tolstring(L, i, nullptr);  // may run __tostring: before anything is written
  std::size_t total = 1;
  for (int i = n + 1; i <= 2 * n; ++i) total += lua_rawlen(L, i) + (i > n + 1 ? 1 : 0);
  if (!LuaSandbox::of(L).spendPrintBudget(total)) return 0;
  for (int i = n + 1; i <= 2 * n; ++i) {
    std::size_t length = 0;
    const char* text = lua_tolstring(L, i, &length);
    if (i > n + 1) std::fputc('\t', stderr);
    std::fwrite(text, 1, length, stderr);
  }
  std::fputc('\n', stderr);
  return 0;
}

// setmetatable() without __gc: finalizers would run Lua code whenever the
// collector runs, including during host-side work outside any protected call
// and outside the quota. Everything else matches the base library.
int sandboxSetmetatable(lua_State* L) {
  const int metatableType = lua_type(L, 2);
  luaL_checktype(L, 1, LUA_TTABLE);
  luaL_argexpected(L, metatableType == LUA_TNIL || metatableType == LUA_TTABLE, 2, "nil or table");
  if (metatableType == LUA_TTABLE) {
    lua_pushliteral(L, "__gc");
    if (lua_rawget(L, 2) != LUA_TNIL) return luaL_error(L, "__gc metamethods are not available in the sandbox");
    lua_pop(L, 1);
  }
  if (luaL_getmetafield(L, 1, "__metatable") != LUA_TNIL) return luaL_error(L, "cannot change a protected metatable");
  lua_settop(L, 2);
  lua_setmetatable(L, 1);
  return 1;
}

// xpcall(f, handler, ...) with the handler run after the error has unwound,
// not at the point of the error. Lua runs a message handler where the error
// was raised, and an instruction-quota error is raised inside the count
// hook, where hooks are off: a handler that loops would run forever. Here
// the handler runs with hooks on (the inner protected call restored them),
// so the quota stops it too. The handler sees the error value, not the stack
// where it was raised (debug.traceback is not in the sandbox anyway).
int sandboxXpcall(lua_State* L) {
  const int n = lua_gettop(L);
  luaL_checktype(L, 2, LUA_TFUNCTION);
  lua_pushvalue(L, 1);
  for (int i = 3; i <= n; ++i) lua_pushvalue(L, i);
  if (lua_pcall(L, n - 2, LUA_MULTRET, 0) == LUA_OK) {
    lua_pushboolean(L, 1);
    lua_insert(L, n + 1);
    return lua_gettop(L) - n;
  }
  lua_pushvalue(L, 2);
  lua_insert(L, -2);
  lua_call(L, 1, 1);
  lua_pushboolean(L, 0);
  lua_insert(L, -2);
  return 2;
}

// Makes every error a one-line string that starts with "file:line:". Errors
// raised with error(msg, 0) or with a non-string value carry no position, so
// the innermost Lua line on the stack is added.
int messageHandler(lua_State* L) {
  const char* message = lua_tostring(L, 1);
  if (message == nullptr) {
    if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING)
      message = lua_tostring(L, -1);
    else
      message = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
  }
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "Sl", &ar);
    if (ar.currentline <= 0) continue;
    const std::size_t sourceLength = std::strlen(ar.short_src);
    if (std::strncmp(message, ar.short_src, sourceLength) == 0 && message[sourceLength] == ':') break;
    lua_pushfstring(L, "%s:%d: %s", ar.short_src, ar.currentline, message);
    return 1;
  }
  lua_pushstring(L, message);
  return 1;
}

// Copies library `lib` into a fresh table, leaving out the names in `excluded`
// (nullptr-terminated). Copies keep the originals unreachable: a script that
// replaces string.format changes only its own view.
void pushLibraryCopy(lua_State* L, int lib, const char* const* excluded) {
  lua_newtable(L);
  const int copy = lua_gettop(L);
  lua_pushnil(L);
  while (lua_next(L, lib) != 0) {
    bool keep = true;
    if (lua_type(L, -2) == LUA_TSTRING) {
      const char* key = lua_tostring(L, -2);
      for (const char* const* name = excluded; *name != nullptr; ++name)
        if (std::strcmp(key, *name) == 0) keep = false;
    }
    if (keep) {
      lua_pushvalue(L, -2);
      lua_insert(L, -2);
      lua_rawset(L, copy);
    } else {
      lua_pop(L, 1);
    }
  }
}

// Builds the allow-list environment and returns it. Run under lua_pcall so
// that even an allocation failure here becomes an ordinary error.
int openSandbox(lua_State* L) {
  luaL_requiref(L, LUA_GNAME, luaopen_base, 0);
  const int globals = lua_gettop(L);
  luaL_requiref(L, LUA_STRLIBNAME, luaopen_string, 0);
  const int stringLib = lua_gettop(L);
  luaL_requiref(L, LUA_TABLIBNAME, luaopen_table, 0);
  const int tableLib = lua_gettop(L);
  luaL_requiref(L, LUA_MATHLIBNAME, luaopen_math, 0);
  const int mathLib = lua_gettop(L);
  luaL_requiref(L, LUA_UTF8LIBNAME, luaopen_utf8, 0);
  const int utf8Lib = lua_gettop(L);

  lua_newtable(L);
  const int env = lua_gettop(L);

  // Base functions that cannot reach the host, load code, or bypass
  // metatables. Left out on purpose: load, loadfile, dofile, require
  // (code loading), collectgarbage (GC control), rawget/rawset (bypass
  // protections levels may put on API tables), print/setmetatable (replaced).
  static const char* const kBaseAllowed[] = {"assert",   "error",  "getmetatable", "ipairs", "next",
                                             "pairs",    "pcall",  "rawequal",     "rawlen", "select",
                                             "tonumber", "tostring", "type",       "xpcall", "_VERSION"};
  for (const char* name : kBaseAllowed) {
    lua_getfield(L, globals, name);
    lua_setfield(L, env, name);
  }
  lua_pushcfunction(L, sandboxPrint);
  lua_setfield(L, env, "print");
  lua_pushcfunction(L, sandboxSetmetatable);
  lua_setfield(L, env, "setmetatable");
  lua_pushcfunction(L, sandboxXpcall);
  lua_setfield(L, env, "xpcall");

  // Before the copy: scripts' libraries and strings' methods (the original
  // string library, through the string metatable) are all bounded.
  installLibraryBounds(L, stringLib, tableLib, utf8Lib, env);
  static const char* const kNothing[] = {nullptr};
  static const char* const kStringExcluded[] = {"dump", nullptr};  // bytecode out
  static const char* const kMathExcluded[] = {"random", "randomseed", nullptr};  // runs must be reproducible
  pushLibraryCopy(L, stringLib, kStringExcluded);
  lua_setfield(L, env, "string");
  pushLibraryCopy(L, tableLib, kNothing);
  lua_setfield(L, env, "table");
  pushLibraryCopy(L, mathLib, kMathExcluded);
  lua_setfield(L, env, "math");
  pushLibraryCopy(L, utf8Lib, kNothing);
  lua_setfield(L, env, "utf8");
  lua_pushvalue(L, env);
  lua_setfield(L, env, "_G");

  // Strings index the ORIGINAL string library through their shared
  // metatable ("x"):rep(3). Hide that metatable (getmetatable("") returns
  // false) and drop dump from the original too.
  lua_pushnil(L);
  lua_setfield(L, stringLib, "dump");
  lua_pushliteral(L, "");
  if (lua_getmetatable(L, -1)) {
    lua_pushboolean(L, 0);
    lua_setfield(L, -2, "__metatable");
  }
  lua_settop(L, env);
  return 1;
}

// True when a message starts with a position "source:line:". Errors raised
// while no Lua function is running (the parser's "C stack overflow", say)
// have none, and get the chunk or callee prefixed instead.
bool hasPosition(const std::string& message) {
  const std::size_t searchLimit = std::min<std::size_t>(message.size(), LUA_IDSIZE + 2);
  for (std::size_t colon = message.find(':'); colon != std::string::npos && colon < searchLimit;
       colon = message.find(':', colon + 1)) {
    std::size_t end = colon + 1;
    while (end < message.size() && message[end] >= '0' && message[end] <= '9') ++end;
    if (end > colon + 1 && end < message.size() && message[end] == ':') return true;
  }
  return false;
}

std::string describeBytes(std::size_t bytes) {
  std::ostringstream out;
  if (bytes % (std::size_t{1} << 20) == 0)
    out << (bytes >> 20) << " MiB";
  else
    out << bytes << " bytes";
  return out.str();
}

}  // namespace

LuaSandbox::LuaSandbox(const SandboxLimits& limits) : limits_(limits) {
  L_ = lua_newstate(&LuaSandbox::allocate, this);
  if (L_ == nullptr) throw ScriptError("cannot create a Lua state (out of memory)");
  *static_cast<LuaSandbox**>(lua_getextraspace(L_)) = this;

  lua_pushcfunction(L_, openSandbox);
  if (lua_pcall(L_, 0, 1, 0) != LUA_OK) {
    const std::string message = lua_tostring(L_, -1) ? lua_tostring(L_, -1) : "unknown error";
    lua_close(L_);
    throw ScriptError("cannot build the Lua sandbox: " + message);
  }
  environmentRef_ = luaL_ref(L_, LUA_REGISTRYINDEX);
}

LuaSandbox::~LuaSandbox() {
  disarm();
  lua_close(L_);
}

void LuaSandbox::pushEnvironment() const {
  lua_checkstack(L_, 1);
  lua_rawgeti(L_, LUA_REGISTRYINDEX, environmentRef_);
}

LuaSandbox& LuaSandbox::of(lua_State* L) { return **static_cast<LuaSandbox**>(lua_getextraspace(L)); }

void* LuaSandbox::allocate(void* ud, void* block, std::size_t oldSize, std::size_t newSize) {
  auto* self = static_cast<LuaSandbox*>(ud);
  const std::size_t old = block != nullptr ? oldSize : 0;  // for new blocks oldSize is a type tag
  if (newSize == 0) {
    std::free(block);
    self->bytesInUse_ -= old;
    return nullptr;
  }
  // Refusing (returning nullptr) makes Lua collect garbage, retry, and then
  // raise a memory error inside the protected call. Shrinking never fails.
  if (self->armed_ && newSize > old && self->bytesInUse_ - old + newSize > self->limits_.memoryLimitBytes)
    return nullptr;
  void* resized = std::realloc(block, newSize);
  if (resized == nullptr) return nullptr;
  self->bytesInUse_ = self->bytesInUse_ - old + newSize;
  return resized;
}

void LuaSandbox::countHook(lua_State* L, lua_Debug* ar) {
  LuaSandbox& self = of(L);
  if (self.limitReached_) {
    lua_getinfo(L, "Sl", ar);
    lua_pushfstring(L, "%s:%d: %s", ar->short_src, ar->currentline, self.limitMessage_);
    lua_error(L);
  }
  self.instructionsUsed_ += static_cast<std::uint64_t>(self.hookInterval_);
  const Clock::time_point now = Clock::now();
  char why[sizeof self.limitMessage_];
  if (now >= self.nextCheck_ && !self.timeAllows(now, why, sizeof why)) raiseLimit(L, why);
  if (self.instructionsUsed_ > self.instructionBudget_) {
    std::snprintf(why, sizeof why, "instruction quota of %llu instructions exceeded (endless loop?)",
                  static_cast<unsigned long long>(self.instructionBudget_));
    raiseLimit(L, why);
  }
  self.adaptHookInterval(L, now);
}

void LuaSandbox::adaptHookInterval(lua_State* L, Clock::time_point now) {
  const Clock::duration since = now - lastHook_;
  lastHook_ = now;
  int next = hookInterval_;
  if (since > kHookTarget && next > 1)
    next = std::max(1, next / 10);
  else if (since < kHookTarget / 20 && next < kHookInterval)
    next = std::min(kHookInterval, next * 10);
  if (next != hookInterval_) {
    hookInterval_ = next;
    lua_sethook(L, &LuaSandbox::countHook, LUA_MASKCOUNT, next);
  }
}

void LuaSandbox::raiseLimit(lua_State* L, const char* message) {
  LuaSandbox& self = of(L);
  if (message != self.limitMessage_) std::snprintf(self.limitMessage_, sizeof self.limitMessage_, "%s", message);
  self.limitReached_ = true;
  // From now on the hook fires on every instruction: a script that catches
  // the error with its own pcall fails again at its very next instruction,
  // so it cannot swallow the limit and carry on.
  self.hookInterval_ = 1;
  lua_sethook(L, &LuaSandbox::countHook, LUA_MASKCOUNT, 1);
  lua_Debug ar;
  for (int level = 0; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "Sl", &ar);
    if (ar.currentline > 0) {
      lua_pushfstring(L, "%s:%d: %s", ar.short_src, ar.currentline, self.limitMessage_);
      lua_error(L);
    }
  }
  lua_pushstring(L, self.limitMessage_);
  lua_error(L);
  std::abort();  // lua_error does not return
}

bool LuaSandbox::timeAllows(Clock::time_point now, char* why, std::size_t size) {
  if (now >= wallDeadline_) {
    std::snprintf(why, size, wallSeconds_ == std::floor(wallSeconds_) ? "wall-clock limit of %.1f s exceeded"
                                                                       : "wall-clock limit of %g s exceeded",
                  wallSeconds_);
    return false;
  }
  if (runBudget_ && now >= runDeadline_) {
    const double spent = runSpent_ + std::chrono::duration<double>(now - armedAt_).count();
    std::snprintf(why, size,
                  "the trial's Lua time budget is spent: %.2f s in Lua by %.3f s of simulated time (a trial run "
                  "headless allows %g s + %g s per simulated second)",
                  spent, simulatedSeconds_, limits_.trialSeconds, limits_.trialSecondsPerSimulatedSecond);
    return false;
  }
  if (cpuSeconds_ > 0.0 && now >= cpuCheck_) {
    const double used = threadCpuSeconds() - cpuStart_;
    if (used > cpuSeconds_) {
      std::snprintf(why, size, "used more than its %g ms of CPU per tick (a real-time tick's deadline)",
                    1e3 * cpuSeconds_);
      return false;
    }
    // Wall time runs at least as fast as the thread's CPU time: the budget
    // cannot run out before the rest of it has passed on the wall clock.
    cpuCheck_ = now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(cpuSeconds_ - used));
  }
  nextCheck_ = std::min(wallDeadline_, cpuSeconds_ > 0.0 ? cpuCheck_ : Clock::time_point::max());
  if (runBudget_) nextCheck_ = std::min(nextCheck_, runDeadline_);
  return true;
}

LuaSandbox::LibraryVerdict LuaSandbox::admitLibraryCall(const char* name, double worstSteps, double chargeSteps,
                                                        const char* detail, char* why, std::size_t size) {
  if (limitReached_) {
    std::snprintf(why, size, "%s", limitMessage_);
    return LibraryVerdict::LimitReached;
  }
  if (!armed_) return LibraryVerdict::Run;  // host-side use between calls: nothing to meter
  if (!(worstSteps <= stepCap_)) {
    std::snprintf(why, size, "%s: %s may take up to %.1e steps, more than the %.1e one library call may take %s",
                  name, detail[0] != '\0' ? detail : "this call", worstSteps, stepCap_,
                  stepCap_ < limits_.libraryStepBound ? "within this call's time limit" : "in the sandbox");
    return LibraryVerdict::Refused;
  }
  const Clock::time_point now = Clock::now();
  if (now >= nextCheck_ && !timeAllows(now, why, size)) return LibraryVerdict::LimitReached;
  chargedSteps_ += chargeSteps / limits_.libraryStepsPerInstruction;
  if (chargedSteps_ >= 1.0) {
    const double whole = std::floor(chargedSteps_);
    chargedSteps_ -= whole;
    instructionsUsed_ += whole >= 1e18 ? std::uint64_t{1} << 60 : static_cast<std::uint64_t>(whole);
  }
  if (instructionsUsed_ > instructionBudget_) {
    std::snprintf(why, size, "instruction quota of %llu instructions exceeded (with the work of %s)",
                  static_cast<unsigned long long>(instructionBudget_), name);
    return LibraryVerdict::LimitReached;
  }
  return LibraryVerdict::Run;
}

bool LuaSandbox::libraryCallReturned(char* why, std::size_t size) {
  if (!armed_) return true;
  const Clock::time_point now = Clock::now();
  return now < nextCheck_ || timeAllows(now, why, size);
}

void LuaSandbox::setTiming(const TrialTiming& timing) {
  if (timing.realtime) {
    setTickCpuLimit(timing.tickSeconds);
    runBudget_ = false;
  } else {
    setTickCpuLimit(0.0);
    startRun();
  }
}

void LuaSandbox::startRun() {
  runBudget_ = true;
  runSpent_ = 0.0;
  simulatedSeconds_ = 0.0;
}

bool LuaSandbox::spendPrintBudget(std::size_t bytes) {
  if (!printCut_ && bytesPrinted_ + bytes <= limits_.printBudgetBytes) {
    bytesPrinted_ += bytes;
    return true;
  }
  if (!printCut_)
    std::fprintf(stderr, "(print: the script's output budget of %zu bytes is spent; further prints are dropped)\n",
                 limits_.printBudgetBytes);
  printCut_ = true;
  return false;
}

void LuaSandbox::arm(std::uint64_t quota, double wallSeconds, double cpuSeconds) {
  instructionBudget_ = quota;
  instructionsUsed_ = 0;
  chargedSteps_ = 0.0;
  limitReached_ = false;
  wallSeconds_ = wallSeconds;
  cpuSeconds_ = cpuSeconds;
  armedAt_ = lastHook_ = Clock::now();
  const auto after = [this](double seconds) {
    return armedAt_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(std::max(0.0, seconds)));
  };
  wallDeadline_ = after(wallSeconds);
  if (cpuSeconds > 0.0) {
    cpuStart_ = threadCpuSeconds();
    cpuCheck_ = after(cpuSeconds);
  }
  if (runBudget_) {
    const double allowed = limits_.trialSeconds + limits_.trialSecondsPerSimulatedSecond * simulatedSeconds_;
    runDeadline_ = after(std::min(allowed - runSpent_, 1e9));
  }
  nextCheck_ = std::min(wallDeadline_, cpuSeconds > 0.0 ? cpuCheck_ : Clock::time_point::max());
  if (runBudget_) nextCheck_ = std::min(nextCheck_, runDeadline_);
  // What one library call may take: the bound, or what this call's time
  // limit allows (a real-time tick's few milliseconds).
  stepCap_ = std::min(limits_.libraryStepBound,
                      limits_.libraryStepsPerSecond * (cpuSeconds > 0.0 ? std::min(cpuSeconds, wallSeconds) : wallSeconds));
  hookInterval_ = kFirstHookInterval;
  lua_sethook(L_, &LuaSandbox::countHook, LUA_MASKCOUNT, kFirstHookInterval);
  armed_ = true;
}

void LuaSandbox::disarm() {
  if (armed_ && runBudget_) runSpent_ += std::chrono::duration<double>(Clock::now() - armedAt_).count();
  armed_ = false;
  limitReached_ = false;
  lua_sethook(L_, nullptr, 0, 0);
}

int LuaSandbox::protectedCall(int nargs, int nresults, std::uint64_t quota, double wallSeconds, double cpuSeconds,
                              std::string_view where, std::string& error) {
  lua_State* L = L_;
  const int function = lua_gettop(L) - nargs;
  if (!lua_checkstack(L, 2)) {
    error = std::string(where) + ": Lua stack overflow";
    lua_settop(L, function - 1);
    return LUA_ERRRUN;
  }
  lua_pushcfunction(L, messageHandler);
  lua_insert(L, function);
  arm(quota, wallSeconds, cpuSeconds);
  const int status = lua_pcall(L, nargs, nresults, function);
  disarm();
  if (status == LUA_OK) {
    lua_remove(L, function);
    return LUA_OK;
  }
  // A memory error passed on by a bounded library call (LuaLibraryBounds)
  // arrives as an ordinary error with Lua's memory message.
  const bool memory = status == LUA_ERRMEM || (lua_type(L, -1) == LUA_TSTRING &&
                                                std::string_view(lua_tostring(L, -1)).ends_with("not enough memory"));
  if (memory) {
    error = std::string(where) + ": memory limit of " + describeBytes(limits_.memoryLimitBytes) + " exceeded";
  } else if (lua_type(L, -1) == LUA_TSTRING) {
    error = lua_tostring(L, -1);
    if (status == LUA_ERRERR || !hasPosition(error)) error = std::string(where) + ": " + error;
  } else {
    error = std::string(where) + ": unknown Lua error";
  }
  lua_settop(L, function - 1);
  return status;
}

void LuaSandbox::runChunk(std::string_view source, const std::string& chunkName, int nresults) {
  // lua_load decides text or binary by the first byte; refuse bytecode here
  // with a clear sentence (the "t" mode below refuses it as well).
  if (!source.empty() && source.front() == LUA_SIGNATURE[0])
    throw ScriptError(chunkName + ": precompiled (binary) Lua chunks are refused; give Lua source text");
  lua_State* L = L_;
  if (!lua_checkstack(L, nresults + 4)) throw ScriptError(chunkName + ": Lua stack overflow");

  const std::string name = "@" + chunkName;
  arm(limits_.chunkInstructionQuota, limits_.chunkWallSeconds, 0.0);  // the memory cap also bounds what the parser may build
  const int loaded = luaL_loadbufferx(L, source.data(), source.size(), name.c_str(), "t");
  disarm();
  if (loaded != LUA_OK) {
    std::string message;
    if (loaded == LUA_ERRMEM || lua_type(L, -1) != LUA_TSTRING) {
      message = chunkName + ": memory limit of " + describeBytes(limits_.memoryLimitBytes) + " exceeded while compiling";
    } else {
      message = lua_tostring(L, -1);
      if (!hasPosition(message)) message = chunkName + ": " + message;
      // Lua's parser recurses once per open bracket, parenthesis or block and
      // stops at LUAI_MAXCCALLS (200); its words for it are about C, and its
      // line is where it gave up, at or after the deepest one.
      if (const std::size_t at = message.rfind("C stack overflow"); at != std::string::npos)
        message = message.substr(0, at) +
                  "nested too deeply (Lua reads at most about 200 levels of brackets, parentheses or blocks; "
                  "this line or one before it goes deeper)";
    }
    lua_pop(L, 1);
    throw ScriptError(message);
  }
  // A main chunk's only upvalue is _ENV: point it at the sandbox environment.
  lua_rawgeti(L, LUA_REGISTRYINDEX, environmentRef_);
  if (lua_setupvalue(L, -2, 1) == nullptr) lua_pop(L, 1);

  std::string error;
  if (protectedCall(0, nresults, limits_.chunkInstructionQuota, limits_.chunkWallSeconds, 0.0, chunkName, error) !=
      LUA_OK)
    throw ScriptError(error);
}

void LuaSandbox::runFile(const std::string& path, int nresults) {
  runChunk(readScriptText(path, "file", limits_.memoryLimitBytes, "memory limit"), path, nresults);
}

int LuaSandbox::call(int nargs, int nresults, std::string_view where) {
  const int base = lua_gettop(L_) - nargs - 1;
  std::string error;
  if (protectedCall(nargs, nresults, limits_.callInstructionQuota, limits_.callWallSeconds, 0.0, where, error) !=
      LUA_OK)
    throw ScriptError(error);
  return lua_gettop(L_) - base;
}

int LuaSandbox::callPerTick(int nargs, int nresults, std::string_view where) {
  const int base = lua_gettop(L_) - nargs - 1;
  std::string error;
  if (protectedCall(nargs, nresults, limits_.callInstructionQuota, limits_.callWallSeconds, tickCpuLimit_, where,
                    error) != LUA_OK)
    throw ScriptError(error);
  return lua_gettop(L_) - base;
}

}  // namespace hemiroll::script
