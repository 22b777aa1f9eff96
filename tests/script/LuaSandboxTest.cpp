// engine/script/LuaSandbox: the allow-list, text-only loading, the quota, the
// memory cap, and errors as "file:line: message".

#include "engine/script/LuaSandbox.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <lua.hpp>
#include <string>

#include "engine/script/ScriptError.h"
#include "tests/script/support/RunChunk.h"

namespace hemiroll::script {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

using test::run;
using test::runFresh;

// Precompiled bytecode for `source`, made by an ordinary (unsandboxed) state.
std::string bytecodeOf(const std::string& source) {
  lua_State* L = luaL_newstate();
  EXPECT_EQ(luaL_loadstring(L, source.c_str()), LUA_OK);
  std::string bytes;
  lua_dump(
      L,
      [](lua_State*, const void* p, size_t n, void* ud) {
        static_cast<std::string*>(ud)->append(static_cast<const char*>(p), n);
        return 0;
      },
      &bytes, 0);
  lua_close(L);
  return bytes;
}

TEST(LuaSandbox, AllowedLibrariesWork) {
  EXPECT_EQ(runFresh("return string.rep('ab', 3) .. ('x'):upper()"), "abababX");
  EXPECT_EQ(runFresh("return table.concat({1, 2, 3}, ',')"), "1,2,3");
  EXPECT_EQ(runFresh("return tostring(math.floor(2.5) + math.max(1, 4))"), "6");
  EXPECT_EQ(runFresh("return utf8.char(72, 105)"), "Hi");
  EXPECT_EQ(runFresh("local s = 0 for _, v in ipairs({1, 2}) do s = s + v end return tostring(s)"), "3");
  EXPECT_EQ(runFresh("return tostring(select('#', 1, 2, 3))"), "3");
  EXPECT_EQ(runFresh("return tostring(pcall(error, 'x'))"), "false");
  EXPECT_EQ(runFresh("return _G == _ENV and _G.string == string"), "true");
}

// Every name a script must not reach is absent from its environment.
class SandboxRefuses : public ::testing::TestWithParam<const char*> {};

TEST_P(SandboxRefuses, NameIsNil) {
  EXPECT_EQ(runFresh(std::string("return ") + GetParam() + " == nil"), "true") << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Escapes, SandboxRefuses,
                         ::testing::Values("io", "os", "debug", "package", "require", "load", "loadfile",
                                           "dofile", "collectgarbage", "rawset", "rawget", "coroutine",
                                           "loadstring", "math.random", "math.randomseed", "string.dump",
                                           "('').dump"));

TEST(LuaSandbox, UsingARefusedLibraryIsAPositionedError) {
  const std::string message = runFresh("local x = 1\nreturn io.open('/etc/passwd')");
  EXPECT_THAT(message, HasSubstr("ERROR: t.lua:2:"));
  EXPECT_THAT(message, HasSubstr("'io'"));
  EXPECT_THAT(runFresh("return os.exit(3)"), HasSubstr("ERROR: t.lua:1:"));
  EXPECT_THAT(runFresh("return require('os')"), HasSubstr("ERROR: t.lua:1:"));
  EXPECT_THAT(runFresh("return debug.getregistry()"), HasSubstr("ERROR: t.lua:1:"));
}

TEST(LuaSandbox, StringMetatableIsHidden) {
  EXPECT_EQ(runFresh("return getmetatable('')"), "false");
  EXPECT_THAT(runFresh("return getmetatable('').__index"), HasSubstr("ERROR: t.lua:1:"));
  EXPECT_THAT(runFresh("return setmetatable('', {})"), HasSubstr("ERROR: t.lua:1:"));
  // The script's `string` is a copy: replacing its functions leaves the
  // methods of strings (the original library) alone.
  EXPECT_EQ(runFresh("string.format = nil; string.rep = nil; return ('%d'):format(7) .. ('a'):rep(2)"), "7aa");
}

TEST(LuaSandbox, FinalizersAreRefused) {
  EXPECT_THAT(runFresh("setmetatable({}, {__gc = function() while true do end end})"),
              HasSubstr("__gc metamethods are not available"));
  EXPECT_EQ(runFresh("return getmetatable(setmetatable({}, {__index = {a = 'ok'}})).__index.a"), "ok");
  EXPECT_THAT(runFresh("local t = setmetatable({}, {__metatable = 'locked'}) return setmetatable(t, {})"),
              HasSubstr("protected metatable"));
}

TEST(LuaSandbox, BinaryChunksAreRefused) {
  const std::string bytecode = bytecodeOf("return 42");
  ASSERT_FALSE(bytecode.empty());
  LuaSandbox sandbox;
  const std::string message = run(sandbox, bytecode);
  EXPECT_THAT(message, HasSubstr("ERROR: t.lua:"));
  EXPECT_THAT(message, HasSubstr("binary"));
}

TEST(LuaSandbox, SyntaxErrorsNameFileAndLine) {
  const std::string message = runFresh("local a = 1\nlocal b = = 2\n");
  EXPECT_THAT(message, HasSubstr("ERROR: t.lua:2:"));
}

TEST(LuaSandbox, RuntimeErrorsNameFileAndLine) {
  EXPECT_THAT(runFresh("local t\n\nreturn t.x"), HasSubstr("ERROR: t.lua:3: attempt to index a nil value"));
  EXPECT_THAT(runFresh("error('plain')"), HasSubstr("ERROR: t.lua:1: plain"));
  // No position from error(msg, 0) or a non-string error: the line is added.
  EXPECT_THAT(runFresh("\nerror('bare', 0)"), HasSubstr("ERROR: t.lua:2: bare"));
  EXPECT_THAT(runFresh("error({})"), HasSubstr("ERROR: t.lua:1: (error object is a table value)"));
  // Errors raised inside library functions point at the calling line.
  EXPECT_THAT(runFresh("\n\nreturn string.rep()"), HasSubstr("ERROR: t.lua:3: bad argument #1 to 'rep'"));
}

TEST(LuaSandbox, StackExhaustionIsAnErrorNotACrash) {
  EXPECT_THAT(runFresh("local function f(n) return f(n + 1) + 1 end\nreturn f(1)"),
              HasSubstr("ERROR: t.lua:1: stack overflow"));
  // The parser's own recursion limit fires with no Lua function running: the
  // chunk name is added so the message still names the file.
  EXPECT_THAT(runFresh("return " + std::string(1000, '{') + std::string(1000, '}')),
              HasSubstr("ERROR: t.lua: nested too deeply (Lua reads at most about 200 levels"));
  // Said in the file's words, not the C library's.
  EXPECT_THAT(runFresh("local x = 1\nreturn " + std::string(300, '(') + "1" + std::string(300, ')')),
              Not(HasSubstr("C stack")));
}

TEST(LuaSandbox, ErrorObjectsWithEndlessTostringAreStopped) {
  SandboxLimits limits;
  limits.chunkInstructionQuota = 100'000;
  EXPECT_THAT(runFresh("error(setmetatable({}, {__tostring = function() while true do end end}))", limits),
              HasSubstr("ERROR: t.lua"));
  EXPECT_EQ(runFresh("error(setmetatable({}, {__tostring = function() return 'custom' end}))"),
            "ERROR: t.lua:1: custom");
}

TEST(LuaSandbox, InstructionQuotaStopsEndlessLoops) {
  SandboxLimits limits;
  limits.chunkInstructionQuota = 100'000;
  const std::string message = runFresh("local i = 0\nwhile true do i = i + 1 end", limits);
  EXPECT_THAT(message, HasSubstr("ERROR: t.lua:2: instruction quota of 100000 instructions exceeded"));
}

TEST(LuaSandbox, QuotaCannotBeSwallowedByPcall) {
  SandboxLimits limits;
  limits.chunkInstructionQuota = 100'000;
  const std::string message =
      runFresh("while true do pcall(function() while true do end end) end return 'escaped'", limits);
  EXPECT_THAT(message, HasSubstr("instruction quota"));
}

TEST(LuaSandbox, QuotaCannotBeEscapedThroughXpcallsHandler) {
  // Lua runs a message handler where the error is raised; a quota error is
  // raised in the count hook, with hooks off, so a looping handler used to
  // spin for ever (issue 19). The sandbox's xpcall runs it after unwinding.
  SandboxLimits limits;
  limits.chunkInstructionQuota = 100'000;
  EXPECT_THAT(runFresh("xpcall(function() while true do end end, function() while true do end end) return 'escaped'",
                       limits),
              HasSubstr("ERROR: t.lua:1: instruction quota of 100000 instructions exceeded"));
  EXPECT_THAT(runFresh("while true do xpcall(function() while true do end end, function(e) return e end) end", limits),
              HasSubstr("instruction quota"));
}

TEST(LuaSandbox, XpcallStillHandsTheErrorToItsHandlerAndPassesArguments) {
  EXPECT_EQ(runFresh("local ok, v = xpcall(function() error('boom', 0) end, function(e) return 'handled ' .. e end)\n"
                     "return tostring(ok) .. ' ' .. v"),
            "false handled boom");
  EXPECT_EQ(runFresh("local ok, a, b = xpcall(function(x, y) return x + y, 'two' end, error, 1, 2)\n"
                     "return tostring(ok) .. ' ' .. a .. ' ' .. b"),
            "true 3 two");
  EXPECT_THAT(runFresh("xpcall(function() end)"), HasSubstr("bad argument #2 to 'xpcall'"));
}

TEST(LuaSandbox, PathologicalPatternsAreRefusedBeforeTheyRun) {
  // .-.-.-.-.-b on 100k characters backtracks for minutes inside C, where
  // no hook runs; the bound refuses it at once, on every way in.
  const std::string subject = "local s = string.rep('a', 100000)\n";
  for (const char* call : {"s:find('.-.-.-.-.-b')", "string.find(s, '.-.-.-.-.-b')", "s:match('.-.-.-.-.-b')",
                           "s:gsub('.-.-.-.-.-b', '')", "for w in s:gmatch('.-.-.-.-.-b') do end"})
    EXPECT_THAT(runFresh(subject + call), HasSubstr("t.lua:2: string.")) << call;
  EXPECT_THAT(runFresh(subject + "s:find('.-.-.-.-.-b')"),
              HasSubstr("string.find: the pattern (5 repeated items) on 100000 characters may take up to 2.5e+28 "
                        "steps, more than the 2.0e+08 one library call may take in the sandbox (anchor it"));
  // Plain finds, anchored and everyday patterns run as before.
  EXPECT_EQ(runFresh(subject + "return tostring(s:find('b', 1, true))"), "nil");
  EXPECT_EQ(runFresh("return (('key = value'):match('^(%w+)%s*=%s*(.-)$'))"), "key");
  EXPECT_EQ(runFresh("return (string.gsub('a,b,,c', ',+', ';'))"), "a;b;c");
}

TEST(LuaSandbox, PrintHasAnOutputBudgetToldOnce) {
  // A bot printing every tick once wrote 19.8 GB in a minute (issue 19).
  SandboxLimits limits;
  limits.printBudgetBytes = 100;
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(runFresh("for i = 1, 1000 do print(string.rep('p', 39)) end return 'done'", limits), "done");
  const std::string err = ::testing::internal::GetCapturedStderr();
  // Two lines of 40 bytes fit in 100; the third does not, and is told once.
  EXPECT_EQ(err, std::string(39, 'p') + "\n" + std::string(39, 'p') + "\n" +
                     "(print: the script's output budget of 100 bytes is spent; further prints are dropped)\n");
}

TEST(LuaSandbox, AWallClockLimitStandsBehindTheQuota) {
  // Work well inside the instruction quota, under a clock already run out:
  // the first count hook (every 1000 instructions) stops it.
  SandboxLimits limits;
  limits.chunkWallSeconds = 0.0;
  EXPECT_THAT(runFresh("local s = 0 for i = 1, 100000 do s = s + i end return 'done'", limits),
              HasSubstr("ERROR: t.lua:1: wall-clock limit of 0.0 s exceeded"));
  // With time to spare the same chunk finishes.
  EXPECT_EQ(runFresh("local s = 0 for i = 1, 100000 do s = s + i end return 'done'"), "done");
}

TEST(LuaSandbox, QuotaAllowsWorkWithinIt) {
  SandboxLimits limits;
  limits.chunkInstructionQuota = 1'000'000;
  EXPECT_EQ(runFresh("local s = 0 for i = 1, 1000 do s = s + i end return tostring(s)", limits), "500500");
}

TEST(LuaSandbox, MemoryCapStopsRunawayAllocation) {
  SandboxLimits limits;
  limits.memoryLimitBytes = std::size_t{2} << 20;
  LuaSandbox sandbox(limits);
  EXPECT_THAT(run(sandbox, "local t = {} for i = 1, 1e8 do t[i] = i end"),
              HasSubstr("ERROR: t.lua: memory limit of 2 MiB exceeded"));
  EXPECT_THAT(run(sandbox, "return string.rep('x', 1 << 22)"), HasSubstr("memory limit of 2 MiB exceeded"));
  // The state survives and the garbage is collectable: a small chunk still runs.
  EXPECT_EQ(run(sandbox, "return 'alive'"), "alive");
  EXPECT_LE(sandbox.memoryInUse(), limits.memoryLimitBytes);
}

TEST(LuaSandbox, PrintWritesToStderrNotStdout) {
  LuaSandbox sandbox;
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  run(sandbox, "print('hello', 1, true)");
  const std::string out = testing::internal::GetCapturedStdout();
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(out, "");
  EXPECT_EQ(err, "hello\t1\ttrue\n");
}

TEST(LuaSandbox, CallUsesThePerCallQuota) {
  SandboxLimits limits;
  limits.callInstructionQuota = 50'000;
  LuaSandbox sandbox(limits);
  sandbox.runChunk("return function(n) local s = 0 for i = 1, n do s = s + i end return s end", "f.lua", 1);
  lua_State* L = sandbox.state();
  const int function = lua_gettop(L);

  lua_pushvalue(L, function);
  lua_pushinteger(L, 100);
  ASSERT_EQ(sandbox.call(1, 1, "f.lua:1"), 1);
  EXPECT_EQ(lua_tointeger(L, -1), 5050);
  lua_pop(L, 1);

  lua_pushvalue(L, function);
  lua_pushinteger(L, 100'000'000);
  try {
    sandbox.call(1, 1, "f.lua:1");
    FAIL() << "expected the per-call quota to stop the call";
  } catch (const ScriptError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("f.lua:1: instruction quota of 50000"));
  }
  EXPECT_EQ(lua_gettop(L), function) << "a failed call leaves the stack as it was";
}

TEST(LuaSandbox, ScriptsCannotReachEachOther) {
  LuaSandbox a, b;
  run(a, "shared = 1");
  EXPECT_EQ(run(b, "return shared == nil"), "true");
}

}  // namespace
}  // namespace hemiroll::script
