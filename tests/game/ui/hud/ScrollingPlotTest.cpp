#include "game/ui/hud/ScrollingPlot.h"

#include <gtest/gtest.h>

namespace hemiroll::game {
namespace {

TEST(ScrollingPlotTest, KeepsTheNewestSamplesOldestFirstWithinItsCapacity) {
  ScrollingPlot plot(4);
  for (int i = 1; i <= 6; ++i) plot.push(static_cast<float>(i));
  ASSERT_EQ(plot.size(), 4u);
  EXPECT_EQ(plot.capacity(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(plot.at(i), static_cast<float>(i + 3));
  EXPECT_EQ(plot.min(), 3.0f);
  EXPECT_EQ(plot.max(), 6.0f);
  int index = 0;
  EXPECT_EQ(ScrollingPlot::getter(&plot, index), 3.0f);
}

TEST(ScrollingPlotTest, PartlyFilledAndClearedRings) {
  ScrollingPlot plot(8);
  plot.push(-2.0f);
  plot.push(5.0f);
  EXPECT_EQ(plot.size(), 2u);
  EXPECT_EQ(plot.at(0), -2.0f);
  EXPECT_EQ(plot.at(1), 5.0f);
  plot.clear();
  EXPECT_EQ(plot.size(), 0u);
  EXPECT_EQ(plot.min(), 0.0f);  // an empty plot reads 0, not +inf
  plot.push(1.5f);
  EXPECT_EQ(plot.at(0), 1.5f);
}

}  // namespace
}  // namespace hemiroll::game
