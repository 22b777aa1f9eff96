// game/research/sweep/SweepProgress: the bar's text, and nothing drawn when stderr
// is not a terminal.

#include "game/research/sweep/SweepProgress.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

TEST(SweepProgress, TheLineShowsTheBarCountRateAndEta) {
  EXPECT_EQ(progressLine(0, 100, 0, 0.0, 10), "[..........] 0/100 points");
  const std::string half = progressLine(50, 100, 0, 10.0, 10);
  EXPECT_THAT(half, StartsWith("[#####.....] 50/100 points"));
  EXPECT_THAT(half, HasSubstr("5 points/s"));
  EXPECT_THAT(half, HasSubstr("ETA 10 s"));
  // Resumed points are done but were not computed now: not in the rate.
  EXPECT_THAT(progressLine(60, 100, 40, 10.0, 10), HasSubstr("2 points/s  ETA 20 s"));
  EXPECT_THAT(progressLine(100, 100, 0, 4.0, 10), StartsWith("[##########] 100/100"));
}

TEST(SweepProgress, DrawsNothingWithoutATerminal) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  SweepProgress quiet(file, 10, 0, false);
  quiet.update(5);
  quiet.finish(10);
  EXPECT_EQ(std::ftell(file), 0L);
  SweepProgress bar(file, 10, 0, true);
  bar.update(5);
  bar.finish(10);
  EXPECT_GT(std::ftell(file), 0L);
  std::fclose(file);
}

}  // namespace
}  // namespace hemiroll::game
