// game/commands/SimOptions: flag parsing of `hemiroll sim`.

#include "game/commands/SimOptions.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

SimOptionsResult parse(std::vector<std::string> args) { return parseSimOptions(args); }

TEST(SimOptions, ReadsEveryFlagInBothSpellings) {
  const auto r = parse({"s.lua", "--duration", "2.5", "--dt=0.0005", "--integrator", "rk4", "--every=10",
                        "--out", "x.csv"});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.scenarioPath, "s.lua");
  EXPECT_EQ(r.options.duration, 2.5);
  EXPECT_EQ(r.options.timeStep, 0.0005);
  EXPECT_EQ(r.options.integrator, "rk4");
  EXPECT_EQ(r.options.every, 10);
  EXPECT_EQ(r.options.outPath, "x.csv");
  EXPECT_EQ(parse({"s.lua", "--orientation=quaternion"}).options.orientation, "quaternion");
  EXPECT_EQ(parse({"s.lua", "--tol", "1e-9"}).options.tolerance, 1e-9);
}

TEST(SimOptions, DefaultsLeaveTheScenarioInCharge) {
  const auto r = parse({"s.lua"});
  ASSERT_EQ(r.error, "");
  EXPECT_FALSE(r.options.duration.has_value());
  EXPECT_FALSE(r.options.timeStep.has_value());
  EXPECT_FALSE(r.options.integrator.has_value());
  EXPECT_EQ(r.options.every, 1);
  EXPECT_FALSE(r.options.outPath.has_value());
  EXPECT_FALSE(r.options.orientation.has_value());
}

TEST(SimOptions, HelpAndListNeedNoScenario) {
  EXPECT_TRUE(parse({"--help"}).options.help);
  EXPECT_EQ(parse({"--help"}).error, "");
  EXPECT_TRUE(parse({"--integrator", "list"}).options.listIntegrators);
  EXPECT_EQ(parse({"--integrator", "list"}).error, "");
}

TEST(SimOptions, BadFlagsAreExplained) {
  EXPECT_THAT(parse({}).error, HasSubstr("missing the scenario file"));
  EXPECT_THAT(parse({"s.lua", "--fast"}).error, HasSubstr("unknown flag '--fast'"));
  EXPECT_THAT(parse({"s.lua", "--dt"}).error, HasSubstr("--dt needs a value"));
  EXPECT_THAT(parse({"s.lua", "--dt", "abc"}).error, HasSubstr("--dt needs a positive number of seconds, got 'abc'"));
  EXPECT_THAT(parse({"s.lua", "--dt", "0.001x"}).error, HasSubstr("got '0.001x'"));
  EXPECT_THAT(parse({"s.lua", "--dt", "-0.001"}).error, HasSubstr("positive"));
  EXPECT_THAT(parse({"s.lua", "--duration", "0"}).error, HasSubstr("positive"));
  EXPECT_THAT(parse({"s.lua", "--duration", "inf"}).error, HasSubstr("positive"));
  EXPECT_THAT(parse({"s.lua", "--duration", "nan"}).error, HasSubstr("positive"));
  EXPECT_THAT(parse({"s.lua", "--every", "0"}).error, HasSubstr("--every needs a whole number"));
  // A tolerance no double step can meet (issue 19: 1e-300 ran and "succeeded").
  EXPECT_THAT(parse({"s.lua", "--tol", "1e-300"}).error, HasSubstr("--tol needs a tolerance in 1e-15 .. 1"));
  EXPECT_THAT(parse({"s.lua", "--max-rows", "1"}).error, HasSubstr("--max-rows needs a whole number >= 2"));
  EXPECT_THAT(parse({"s.lua", "--every", "2.5"}).error, HasSubstr("--every needs a whole number"));
  EXPECT_THAT(parse({"s.lua", "--integrator", "euler"}).error, HasSubstr("unknown integrator 'euler' (available: rk4"));
  EXPECT_THAT(parse({"s.lua", "t.lua"}).error, HasSubstr("unexpected argument 't.lua'"));
  EXPECT_THAT(parse({"s.lua", "--out="}).error, HasSubstr("--out needs a file name"));
  EXPECT_THAT(parse({"s.lua", "--orientation", "euler"}).error,
              HasSubstr("--orientation needs 'angles' or 'quaternion', got 'euler'"));
}

}  // namespace
}  // namespace hemiroll::game
