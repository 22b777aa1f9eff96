// game/commands AnalyzeOptions: the flags of `hemiroll analyze`.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "game/commands/AnalyzeOptions.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

TEST(AnalyzeOptions, InputsOutAndPlots) {
  AnalyzeOptionsResult r = parseAnalyzeOptions({"a.csv", "session", "--out", "out", "b.csv"});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.inputs, (std::vector<std::string>{"a.csv", "session", "b.csv"}));
  EXPECT_EQ(r.options.outDir, "out");
  EXPECT_TRUE(r.options.plots) << "plots by default when there is somewhere to put them";
  r = parseAnalyzeOptions({"a.csv", "--out=out", "--plots", "none"});
  ASSERT_EQ(r.error, "");
  EXPECT_FALSE(r.options.plots);
  r = parseAnalyzeOptions({"a.csv"});
  ASSERT_EQ(r.error, "");
  EXPECT_FALSE(r.options.plots);
  EXPECT_FALSE(r.options.outDir.has_value());
}

TEST(AnalyzeOptions, MistakesAreOneSentence) {
  EXPECT_EQ(parseAnalyzeOptions({}).error, "missing the recording(s) to analyse");
  EXPECT_THAT(parseAnalyzeOptions({"a.csv", "--plots", "png", "--out", "o"}).error,
              HasSubstr("--plots needs 'svg' or 'none', got 'png'"));
  EXPECT_THAT(parseAnalyzeOptions({"a.csv", "--plots", "svg"}).error, HasSubstr("needs --out DIR"));
  EXPECT_THAT(parseAnalyzeOptions({"a.csv", "--speed", "2"}).error, HasSubstr("--speed"));
  EXPECT_THAT(parseAnalyzeOptions({"a.csv", "--out"}).error, HasSubstr("--out"));
  EXPECT_TRUE(parseAnalyzeOptions({"--help"}).options.help);
}

}  // namespace
}  // namespace hemiroll::game
