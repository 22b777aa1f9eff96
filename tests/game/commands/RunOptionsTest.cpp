// game/commands/RunOptions: the flags of `hemiroll run`, checked before any
// file is read.

#include "game/commands/RunOptions.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

TEST(RunOptions, ReadsEveryFlagInBothSpellings) {
  const RunOptionsResult r =
      parseRunOptions({"level.lua", "--bot", "b.lua", "--seed=42", "--record", "out", "--realtime"});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.levelPath, "level.lua");
  EXPECT_EQ(r.options.botPath, "b.lua");
  EXPECT_EQ(r.options.seed, 42u);
  EXPECT_EQ(r.options.recordDir, "out");
  EXPECT_TRUE(r.options.realtime);
}

TEST(RunOptions, DefaultsAreSeedZeroHeadlessNoRecording) {
  const RunOptionsResult r = parseRunOptions({"--bot=b.lua", "level.lua"});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.seed, 0u);
  EXPECT_FALSE(r.options.recordDir);
  EXPECT_FALSE(r.options.realtime);
}

TEST(RunOptions, LargestSeedIsTheLargestLuaInteger) {
  EXPECT_EQ(parseRunOptions({"l.lua", "--bot", "b", "--seed", "9223372036854775807"}).options.seed,
            9223372036854775807u);
  EXPECT_THAT(parseRunOptions({"l.lua", "--bot", "b", "--seed", "9223372036854775808"}).error,
              HasSubstr("--seed needs a whole number"));
}

TEST(RunOptions, ADeviceBehindTheBridgePlaysInRealTimeWithoutABot) {
  const RunOptionsResult r = parseRunOptions({"level.lua", "--realtime", "--device", "udp", "--port", "50001",
                                              "--client-timeout", "5", "--device-profile", "touch"});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.device, "udp");
  EXPECT_EQ(r.options.port, 50001);
  EXPECT_EQ(r.options.clientTimeout, 5.0);
  EXPECT_EQ(r.options.deviceProfile, "touch");
  EXPECT_EQ(parseRunOptions({"level.lua", "--device", "udp"}).error,
            "--device udp needs --realtime: a person at a device plays on the wall clock");
  EXPECT_EQ(parseRunOptions({"level.lua", "--realtime", "--device", "udp", "--bot", "b.lua"}).error,
            "--device udp and --bot exclude each other: the person at the device plays");
  EXPECT_EQ(parseRunOptions({"level.lua", "--device", "mouse", "--bot", "b.lua"}).error,
            "--device needs bot or udp, not 'mouse'");
  EXPECT_EQ(parseRunOptions({"level.lua", "--realtime", "--device", "udp", "--port", "0"}).error,
            "flag --port needs a port from 1 to 65535, got '0'");
}

TEST(RunOptions, BadFlagsSayWhat) {
  struct Case {
    std::vector<std::string> args;
    const char* expected;
  };
  const Case cases[] = {
      {{}, "missing the level file"},
      {{"l.lua"}, "missing --bot"},
      {{"l.lua", "--bot"}, "flag --bot needs a value"},
      {{"l.lua", "--bot", ""}, "flag --bot needs a bot file"},
      {{"l.lua", "--bot", "b", "--seed", "-1"}, "--seed needs a whole number"},
      {{"l.lua", "--bot", "b", "--seed", "1.5"}, "--seed needs a whole number"},
      {{"l.lua", "--bot", "b", "--seed", ""}, "--seed needs a whole number"},
      {{"l.lua", "--bot", "b", "--record="}, "flag --record needs a directory"},
      {{"l.lua", "--bot", "b", "--fast"}, "unknown flag '--fast'"},
      {{"l.lua", "m.lua", "--bot", "b"}, "unexpected argument 'm.lua'"},
      // A protocol's bounds for guidance (issue 33): 0 to 1e6 N/m, 0 to 1e4 N s/m.
      {{"l.lua", "--bot", "b", "--guidance-stiffness", "1e300"}, "--guidance-stiffness needs a stiffness from 0 to 1e6 N/m"},
      {{"l.lua", "--bot", "b", "--guidance-damping", "-1"}, "--guidance-damping needs a damping from 0 to 1e4 N s/m"},
  };
  for (const Case& c : cases) EXPECT_THAT(parseRunOptions(c.args).error, HasSubstr(c.expected)) << c.expected;
}

// One rule for guidance gains (issue 33): 0 is a damping a protocol may
// give, and so may the flag.
TEST(RunOptions, AZeroGuidanceDampingIsAllowedAsInAProtocol) {
  const RunOptionsResult r = parseRunOptions({"l.lua", "--bot", "b", "--guidance", "autopilot", "--guidance-damping", "0",
                                              "--guidance-stiffness", "0"});
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(r.options.guidanceDamping, 0.0);
  EXPECT_EQ(r.options.guidanceStiffness, 0.0);
}

TEST(RunOptions, HelpNeedsNothingElse) {
  const RunOptionsResult r = parseRunOptions({"--help"});
  EXPECT_EQ(r.error, "");
  EXPECT_TRUE(r.options.help);
}

}  // namespace
}  // namespace hemiroll::game

namespace hemiroll::game {
namespace {

TEST(RunOptions, TheAutopilotTakesABudgetWithinItsRange) {
  const RunOptionsResult ok = parseRunOptions({"level.lua", "--bot", "autopilot", "--autopilot-budget", "2.5"});
  EXPECT_EQ(ok.error, "");
  EXPECT_EQ(ok.options.botPath, "autopilot");
  EXPECT_EQ(ok.options.autopilotBudget, 2.5);
  EXPECT_EQ(parseRunOptions({"level.lua", "--bot", "autopilot"}).options.autopilotBudget, 1.0);
  EXPECT_NE(parseRunOptions({"level.lua", "--bot", "autopilot", "--autopilot-budget", "5"}).error.find("0.25 to 4"),
            std::string::npos);
  EXPECT_NE(parseRunOptions({"level.lua", "--bot", "autopilot", "--autopilot-budget", "x"}).error.find("--autopilot-budget"),
            std::string::npos);
}

TEST(RunOptions, ReadsTheHumanModelsFlagsAndRefusesABadDevice) {
  const RunOptionsResult r = parseRunOptions({"l.lua", "--bot", "human", "--human-delay", "0.25", "--human-interval=0.3",
                                              "--human-noise", "0.15", "--human-device", "haptic", "--human-aids"});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.human.human.visualDelay, 0.25);
  EXPECT_EQ(r.options.human.human.interval, 0.3);
  EXPECT_EQ(r.options.human.human.noise, 0.15);
  EXPECT_EQ(r.options.human.human.device, human::HandDevice::Haptic);
  EXPECT_TRUE(r.options.human.aids);
  EXPECT_TRUE(r.options.human.human.coContracts);
  EXPECT_FALSE(parseRunOptions({"l.lua", "--bot", "human", "--human-device", "haptic", "--human-relaxed-arm"})
                   .options.human.human.coContracts);
  EXPECT_THAT(parseRunOptions({"l.lua", "--bot", "human", "--human-device", "glove"}).error,
              HasSubstr("--human-device needs mouse, mouse-hand or haptic, not 'glove'"));
  EXPECT_THAT(parseRunOptions({"l.lua", "--bot", "human", "--human-delay", "-1"}).error,
              HasSubstr("--human-delay needs a delay from 0 to 2 s"));
}

}  // namespace
}  // namespace hemiroll::game
