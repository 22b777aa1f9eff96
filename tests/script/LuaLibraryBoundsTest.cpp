// engine/script/LuaLibraryBounds: every library function that loops or
// allocates inside C is bounded before it runs (issue 33, item 1), its work
// charged to the quota, the clock read at every call; and the time budgets
// of a trial (item 2): the run's time in Lua headless, a tick's CPU in real
// time. The functions still do what Lua's do.

#include "engine/script/LuaLibraryBounds.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <lua.hpp>
#include <string>

#include "engine/script/LuaSandbox.h"
#include "engine/script/ScriptError.h"
#include "tests/script/support/RunChunk.h"

namespace hemiroll::script {
namespace {

using ::testing::HasSubstr;

using test::run;
using test::runFresh;

double secondsOf(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The calls the red team found, and their kin: each refused at once, before
// it runs, by the way scripts reach it (the library table and, for strings,
// the method through the string metatable).
TEST(LuaLibraryBounds, CallsThatWouldRunForHoursAreRefusedBeforeTheyStart) {
  const struct {
    const char* code;
    const char* message;
  } cases[] = {
      {"string.rep('', math.maxinteger)", "string.rep: 9223372036854775807 repetitions of 0 bytes may take up to 9.2e+18"},
      {"(''):rep(1e15)", "string.rep: 1000000000000000 repetitions"},
      {"string.rep('', 1e9, '')", "string.rep: 1000000000 repetitions"},
      {"table.move({}, 1, 1e15, 1, {})", "table.move: moving 1000000000000000 elements"},
      {"table.move({}, math.mininteger, -1, 1)", "table.move: moving 9223372036854775808 elements"},
      {"local a = string.rep('a', 1 << 22) local b = string.rep('a', (1 << 21) - 1) .. 'b' a:find(b, 1, true)",
       "string.find: a plain search for 2097152 bytes in 4194304"},
      // No special characters: Lua searches plainly without being asked.
      {"local a = string.rep('a', 1 << 22) local b = string.rep('a', (1 << 21) - 1) .. 'b' return a:find(b)",
       "string.find: a plain search for 2097152 bytes"},
      // %b after a repeat: every length of .- followed by a scan to the end.
      {"local s = string.rep('(', 5000) return s:find('.-%b()')", "string.find: the pattern (1 repeated items) on 5000"},
      // An empty pattern matches at every position; a long replacement made
      // of %0 writes nothing, so memory does not stop it.
      {"local s = string.rep('x', 1e5) return (s:gsub('', string.rep('%0', 1e5)))", "string.gsub: "},
      // A stateful __len could answer small to the bound and huge to the function.
      {"local t = setmetatable({}, {__len = function() return 1e15 end}) table.insert(t, 1, 1)",
       "table.insert: a table with a __len metamethod"},
      {"local t = setmetatable({}, {__len = function() return 1e15 end}) table.sort(t)", "table.sort: a table with"},
      {"local t = setmetatable({}, {__len = function() return 1e15 end}) table.remove(t, 1)", "table.remove: a table"},
      // concat and unpack are handed the length read once, as their range.
      {"local t = setmetatable({}, {__len = function() return 1e15 end}) return table.concat(t)",
       "table.concat: 1000000000000000 elements"},
      {"return string.pack('c2000000000', '')", "string.pack: "},
  };
  for (const auto& c : cases) {
    const auto start = std::chrono::steady_clock::now();
    const std::string result = runFresh(c.code);
    EXPECT_THAT(result, HasSubstr("ERROR: t.lua:1: ")) << c.code;
    EXPECT_THAT(result, HasSubstr(c.message)) << c.code;
    EXPECT_THAT(result, HasSubstr("more than the 2.0e+08 one library call may take in the sandbox")) << c.code;
    // Refused, not run: far under the 10 s a chunk may take.
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0) << c.code;
  }
}

// The same functions on everyday arguments behave as Lua's, and their
// argument errors name them as Lua's do.
TEST(LuaLibraryBounds, EverydayCallsWorkAsLuasDo) {
  EXPECT_EQ(runFresh("return ('ab'):rep(3, '-')"), "ab-ab-ab");
  EXPECT_EQ(runFresh("return string.rep('x', 0) .. '|' .. string.rep('x', -5)"), "|");
  EXPECT_EQ(runFresh("return tostring(('hello'):find('l'))"), "3");
  EXPECT_EQ(runFresh("return tostring(('a.b'):find('.', 1, true))"), "2");
  EXPECT_EQ(runFresh("return (('key = value'):match('^(%w+)%s*=%s*(.-)$'))"), "key");
  EXPECT_EQ(runFresh("local n = 0 for w in ('a bb ccc'):gmatch('%a+') do n = n + #w end return n"), "6");
  EXPECT_EQ(runFresh("return (string.gsub('a,b,,c', ',+', ';'))"), "a;b;c");
  EXPECT_EQ(runFresh("return ('hello'):sub(2, -2) .. ('AbC'):lower() .. ('x'):upper() .. ('abc'):reverse()"),
            "ellabcXcba");
  EXPECT_EQ(runFresh("return string.format('%5.2f|%q|%s', 3.14159, 'a\"b', 7)"), " 3.14|\"a\\\"b\"|7");
  EXPECT_EQ(runFresh("return table.concat({1, 2, 3}, ', ')"), "1, 2, 3");
  EXPECT_EQ(runFresh("return table.concat({1, 2, 3})"), "123");
  EXPECT_EQ(runFresh("return table.concat({1, 2, 3, 4}, '', 2, 3)"), "23");
  EXPECT_EQ(runFresh("local t = {3, 1, 2} table.sort(t) table.insert(t, 4) table.insert(t, 1, 0) "
                     "table.remove(t, 2) return table.concat(t, ',')"),
            "0,2,3,4");
  EXPECT_EQ(runFresh("local t = table.move({1, 2, 3}, 1, 3, 2) return table.concat(t, ',')"), "1,1,2,3");
  EXPECT_EQ(runFresh("return select('#', table.unpack({1, 2, 3})) .. select(2, 'a', 'b')"), "3b");
  EXPECT_EQ(runFresh("local p = table.pack(1, nil, 3) return p.n"), "3");
  EXPECT_EQ(runFresh("return utf8.char(72, 228) .. utf8.len('h\\u{E4}') .. utf8.codepoint('A')"), "H\xC3\xA4" "265");
  EXPECT_EQ(runFresh("return tostring(tonumber('0x10') + tonumber('z', 36))"), "51");
  EXPECT_EQ(runFresh("return string.unpack('i4', string.pack('i4', 42))"), "42");
  // A __len the function would read is read once and given as the range.
  EXPECT_EQ(runFresh("local t = setmetatable({'a', 'b', 'c'}, {__len = function() return 2 end}) "
                     "return table.concat(t) .. select('#', table.unpack(t))"),
            "ab2");
  // Argument errors name the function, as Lua's own do.
  EXPECT_THAT(runFresh("return string.rep()"), HasSubstr("t.lua:1: bad argument #1 to 'rep'"));
  EXPECT_THAT(runFresh("return ('x'):rep('y')"), HasSubstr("t.lua:1: bad argument #2 to 'rep'"));
  EXPECT_THAT(runFresh("return table.concat({{}})"), HasSubstr("in table for 'concat'"));
  EXPECT_THAT(runFresh("return table.insert({}, 1, 2, 3)"), HasSubstr("wrong number of arguments to 'insert'"));
}

// The certain part of a library call's work counts against the quota: a
// loop of large calls ends as a loop of instructions does, not after the
// thousands of seconds its instruction count alone would allow.
TEST(LuaLibraryBounds, ALoopOfLargeCallsMeetsTheQuota) {
  SandboxLimits limits;
  limits.chunkInstructionQuota = 1'000'000;
  const std::string result =
      runFresh("local s = string.rep('a', 1 << 20) for i = 1, 1e6 do local n = utf8.len(s) end", limits);
  EXPECT_THAT(result, HasSubstr("instruction quota of 1000000 instructions exceeded (with the work of utf8.len)"));
}

// The clock is read at every library call, not only every thousand
// instructions: a loop of calls each under the bound (%b() on 5 000
// unbalanced characters: 2.5e7 steps, about 15 ms) stops at the wall
// clock's limit, not a thousand instructions (250 calls, 4 s) later.
TEST(LuaLibraryBounds, TheWallClockIsCheckedAtEveryLibraryCall) {
  SandboxLimits limits;
  limits.chunkWallSeconds = 0.3;
  std::string result;
  const double seconds = secondsOf([&] {
    result = runFresh("local s = string.rep('(', 5000) for i = 1, 1e6 do s:find('%b()') end", limits);
  });
  EXPECT_THAT(result, HasSubstr("wall-clock limit of 0.3 s exceeded"));
  // At most one call late: what one call may take within 0.3 s is 3e7 steps.
  EXPECT_LT(seconds, 1.5);
}

// Where instructions themselves are slow (comparing two 8 MB strings is one
// instruction of milliseconds), the hook comes more often, so the clock is
// still read about every millisecond.
TEST(LuaLibraryBounds, SlowInstructionsBringTheHookCloser) {
  SandboxLimits limits;
  limits.chunkWallSeconds = 0.3;
  std::string result;
  const double seconds = secondsOf([&] {
    result = runFresh("local a = string.rep('a', 8e6) local b = a:sub(1, -2) .. 'b' local n = 0 "
                      "while true do if a < b then n = n + 1 end end",
                      limits);
  });
  EXPECT_THAT(result, HasSubstr("wall-clock limit of 0.3 s exceeded"));
  // Every thousand instructions, 500 comparisons of ~2 ms: a second late.
  EXPECT_LT(seconds, 1.5);
}

// A limit reached inside a library call (here the clock, during a sort's
// comparisons) cannot be swallowed by a pcall around it.
TEST(LuaLibraryBounds, ALimitReachedInALibraryCallCannotBeCaught) {
  SandboxLimits limits;
  limits.chunkInstructionQuota = 200'000;
  EXPECT_THAT(runFresh("local t = {} for i = 1, 2000 do t[i] = -i end "
                       "for k = 1, 1e9 do pcall(table.sort, t, function(a, b) return a < b end) end return 'escaped'",
                       limits),
              HasSubstr("instruction quota of 200000 instructions exceeded"));
}

// Headless, a run's calls together may spend trialSeconds + ... per
// simulated second inside Lua; past it every call fails with the reason.
TEST(LuaTimeBudget, ARunsTimeInLuaIsBoundedByItsSimulatedTime) {
  SandboxLimits limits;
  limits.trialSeconds = 0.05;
  limits.trialSecondsPerSimulatedSecond = 0.0;
  LuaSandbox sandbox(limits);
  sandbox.runChunk("return function() local s = string.rep('(', 5000) s:find('%b()') end", "f.lua", 1);
  lua_State* L = sandbox.state();
  const int function = lua_gettop(L);
  sandbox.startRun();
  std::string error;
  for (int i = 0; i < 1000 && error.empty(); ++i) {
    sandbox.advanceRun(0.001 * i);
    lua_pushvalue(L, function);
    try {
      sandbox.callPerTick(0, 0, "f.lua:1");
    } catch (const ScriptError& e) {
      error = e.what();
    }
  }
  EXPECT_THAT(error, HasSubstr("the trial's Lua time budget is spent"));
  EXPECT_THAT(error, HasSubstr("a trial run headless allows 0.05 s + 0 s per simulated second"));
  EXPECT_GE(sandbox.runSecondsSpent(), 0.05);
  EXPECT_LT(sandbox.runSecondsSpent(), 1.0);
  // A new run starts with its budget whole.
  sandbox.startRun();
  EXPECT_EQ(sandbox.runSecondsSpent(), 0.0);
}

// Real time: a per-tick call has the tick's CPU; the clock of the thread is
// read only once the call has run that long by the wall clock.
TEST(LuaTimeBudget, APerTickCallHasTheTicksCpu) {
  SandboxLimits limits;
  limits.callInstructionQuota = 50'000'000;
  LuaSandbox sandbox(limits);
  sandbox.runChunk("return function(n) local s = 0 for i = 1, n do s = s + i end return s end", "f.lua", 1);
  lua_State* L = sandbox.state();
  const int function = lua_gettop(L);
  sandbox.setTickCpuLimit(0.002);
  lua_pushvalue(L, function);
  lua_pushinteger(L, 100);
  EXPECT_EQ(sandbox.callPerTick(1, 1, "f.lua:1"), 1);  // well inside
  lua_pop(L, 1);
  lua_pushvalue(L, function);
  lua_pushinteger(L, 3'000'000);  // under the quota, far over 2 ms
  try {
    sandbox.callPerTick(1, 1, "f.lua:1");
    FAIL() << "expected the tick's budget to stop the call";
  } catch (const ScriptError& e) {
    EXPECT_THAT(e.what(), HasSubstr("f.lua:1: used more than its 2 ms of CPU per tick"));
  }
  // The same call made as a one-off (call, not callPerTick) has no tick budget.
  lua_pushvalue(L, function);
  lua_pushinteger(L, 3'000'000);
  EXPECT_EQ(sandbox.call(1, 1, "f.lua:1"), 1);
  lua_pop(L, 1);
  // And what a library call may take shrinks with the tick: 2e5 steps.
  sandbox.runChunk("return function() local s = string.rep('(', 1000) s:find('%b()') end", "g.lua", 1);
  try {
    sandbox.callPerTick(0, 0, "g.lua:1");
    FAIL() << "expected the search to be refused";
  } catch (const ScriptError& e) {
    EXPECT_THAT(e.what(), HasSubstr("one library call may take within this call's time limit"));
  }
}

}  // namespace
}  // namespace hemiroll::script
