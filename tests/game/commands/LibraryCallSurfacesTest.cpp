// Issue 33, item 1: one library call that loops or allocates inside C
// (string.rep('', math.maxinteger), table.move({}, 1, 1e15, 1, {}), a plain
// string.find of an 8 MB needle in a 16 MB subject) once ran for hours on
// every Lua surface, past the instruction quota and the wall clock. Each is
// put on each surface and run through the real binary: a level's top,
// on_start, score and on_fail, a bot's top and act (headless and in real
// time), a protocol, a sweep spec, a scenario's top and proxy. Every run
// must end in seconds (a `timeout` of 30 s stands guard) with the refusal
// naming the function. The window's level list is tested with the screens.
//
// Item 2: a search just under the bound, called every tick, ends the trial
// on its time budget (headless) or on the tick's CPU budget (real time).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/ProcessRunner.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::test {
namespace {

using ::testing::HasSubstr;

const std::string kBinary = HEMIROLL_BINARY;
const std::string kLevels = std::string(HEMIROLL_SOURCE_DIR) + "/levels";

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// hemiroll under a 30 s guard: exit code 124 means it had to be killed.
ProcessResult hemiroll(const std::vector<std::string>& args) {
  std::vector<std::string> all = {"30", kBinary};
  all.insert(all.end(), args.begin(), args.end());
  return runProcess("/usr/bin/timeout", all);
}

struct Escape {
  const char* name;
  const char* setup;     // at the file's top (the operands)
  const char* code;      // the one call, where the surface runs it
  const char* function;  // what the refusal names
};

const Escape kEscapes[] = {
    {"rep", "", "local s = string.rep('', math.maxinteger)", "string.rep: "},
    {"move", "", "table.move({}, 1, 1e15, 1, {})", "table.move: "},
    {"plainFind",
     "local big_a = string.rep('a', 16 * 1024 * 1024) local big_b = string.rep('a', 8 * 1024 * 1024 - 1) .. 'b'",
     "big_a:find(big_b, 1, true)", "string.find: "},
};
void PrintTo(const Escape& e, std::ostream* os) { *os << e.name; }

// A bot that plays nothing: the proxy held at the face centre.
constexpr const char* kIdleBot = "return { name = 'idle', act = function(t, obs) return 0, 0, 0.04 end }\n";

class LibraryCallSurfacesTest : public ::testing::TestWithParam<Escape> {
 protected:
  // tutorial 01 with `code` put in at `where` ("top", "on_start", "score",
  // "on_fail"; the level fails at once on_fail's way: a time limit of 0.01 s).
  std::string level(const std::string& where) const {
    std::string text = readFile(kLevels + "/tutorial_01_tilt_and_return.lua");
    const std::string code = GetParam().code;
    if (where == "top") text = code + "\n" + text;
    text = std::string(GetParam().setup) + "\n" + text;
    if (where == "on_start") replace(text, "told_to_return = false\n", "told_to_return = false\n" + code + "\n");
    if (where == "score") replace(text, "if not s.success then return 0 end", code + "\nif true then return 0 end");
    if (where == "on_fail") {
      replace(text, "on_success = function(state)",
              "on_fail = function(state, reason) " + code + " end,\n    on_success = function(state)");
      replace(text, "time_limit = 60", "time_limit = 0.01");
    }
    return dir_.write("level.lua", text);
  }
  static void replace(std::string& text, const std::string& what, const std::string& with) {
    const std::size_t at = text.find(what);
    ASSERT_NE(at, std::string::npos) << what;
    text.replace(at, what.size(), with);
  }
  // The refusal, in the run's stdout (JSON line) or stderr.
  void expectRefused(const ProcessResult& r, const std::string& where) const {
    EXPECT_NE(r.exitCode, 124) << where << ": killed by the 30 s guard";
    EXPECT_NE(r.exitCode, 0) << where;
    EXPECT_THAT(r.out + r.err, HasSubstr(GetParam().function)) << where;
    EXPECT_THAT(r.out + r.err, HasSubstr("one library call may take")) << where;
  }
  TempDirectory dir_;
};

TEST_P(LibraryCallSurfacesTest, ALevelsTopCallbacksAndScore) {
  const std::string bot = dir_.write("idle.lua", kIdleBot);
  for (const char* where : {"top", "on_start", "score", "on_fail"})
    expectRefused(hemiroll({"run", level(where), "--bot", bot}), where);
}

TEST_P(LibraryCallSurfacesTest, ABotsTopAndActHeadlessAndInRealTime) {
  const std::string good = kLevels + "/tutorial_01_tilt_and_return.lua";
  const std::string top =
      dir_.write("top.lua", std::string(GetParam().setup) + "\n" + GetParam().code + "\n" + kIdleBot);
  expectRefused(hemiroll({"run", good, "--bot", top}), "bot top");
  const std::string act = dir_.write("act.lua", std::string(GetParam().setup) + "\nreturn { name = 'a', act = function(t, obs) " +
                                                     GetParam().code + " return 0, 0, 0.04 end }\n");
  expectRefused(hemiroll({"run", good, "--bot", act}), "bot act");
  expectRefused(hemiroll({"run", good, "--bot", act, "--realtime"}), "bot act, real time");
}

TEST_P(LibraryCallSurfacesTest, AProtocolASweepSpecAndAScenario) {
  const std::string protocol = dir_.write(
      "p.lua", std::string(GetParam().setup) + "\n" + GetParam().code + "\nreturn { experiment = 'x', blocks = { { level = '" + kLevels +
                   "/tutorial_01_tilt_and_return.lua' } } }\n");
  expectRefused(hemiroll({"session", protocol, "--participant", "p1", "--bot", "autopilot", "--data",
                          (dir_.path() / "data").string()}),
                "protocol");
  const std::string spec = dir_.write(
      "s.lua", std::string(GetParam().setup) + "\n" + GetParam().code +
                   "\nreturn { duration = 1, axes = { { param = 'k', values = { 4, 8 } } } }\n");
  expectRefused(hemiroll({"sweep", spec, "--out", (dir_.path() / "sweep").string()}), "sweep spec");
  std::string scenario = readFile(kLevels + "/scenarios/tether_m3.lua");
  expectRefused(hemiroll({"sim", dir_.write("top.lua", std::string(GetParam().setup) + "\n" + GetParam().code +
                                                          "\n" + scenario)}),
                "scenario top");
  scenario = std::string(GetParam().setup) + "\n" + scenario;
  replace(scenario, "proxy = { x = 0.004, y = 0.0, z = R },",
          std::string("proxy = function(t) ") + GetParam().code + " return 0.004, 0, R end,");
  expectRefused(hemiroll({"sim", dir_.write("proxy.lua", scenario)}), "scenario proxy");
}

INSTANTIATE_TEST_SUITE_P(Escapes, LibraryCallSurfacesTest, ::testing::ValuesIn(kEscapes),
                         [](const ::testing::TestParamInfo<Escape>& info) { return std::string(info.param.name); });

// A search under the bound (0.13 s) every tick: headless the bot's time in
// Lua meets the trial's budget (2 s + 1 s per simulated second) and the
// trial ends with that reason; in real time the first call is refused, a
// tick's 2 ms allowing far fewer steps.
TEST(LuaTimeBudgetTest, ASlowSearchEveryTickEndsTheTrialWithAReason) {
  TempDirectory dir;
  const std::string bot = dir.write(
      "slow.lua", "local s = string.rep('(', 14000)\n"
                  "return { name = 'slow', act = function(t, obs) s:find('%b()') return 0, 0, 0.04 end }\n");
  const std::string level = kLevels + "/tutorial_01_tilt_and_return.lua";
  const ProcessResult headless = hemiroll({"run", level, "--bot", bot});
  EXPECT_EQ(headless.exitCode, 1) << headless.err;
  EXPECT_THAT(headless.out, HasSubstr("\"reason\":\"bot error: "));
  EXPECT_THAT(headless.out, HasSubstr("the trial's Lua time budget is spent"));
  const ProcessResult realtime = hemiroll({"run", level, "--bot", bot, "--realtime"});
  EXPECT_EQ(realtime.exitCode, 1) << realtime.err;
  EXPECT_THAT(realtime.out, HasSubstr("one library call may take within this call's time limit"));
  // Plain Lua over the tick's budget: its CPU is read and the trial ends.
  const std::string busy = dir.write(
      "busy.lua", "return { name = 'busy', act = function(t, obs) local s = 0 for i = 1, 900000 do s = s + i end "
                  "return 0, 0, 0.04 end }\n");
  const ProcessResult spinning = hemiroll({"run", level, "--bot", busy, "--realtime"});
  EXPECT_EQ(spinning.exitCode, 1) << spinning.err;
  EXPECT_THAT(spinning.out, HasSubstr("used more than its 2 ms of CPU per tick"));
}

}  // namespace
}  // namespace hemiroll::test
