// game/research/report PlotAxis: nice ticks in the label's unit, ranges from data.

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "game/research/report/PlotAxis.h"

namespace hemiroll::report {
namespace {

TEST(PlotAxis, MetresShownAsCentimetresWithNiceTicks) {
  const PlotAxis axis(-0.023, 0.023, 100.0);  // the paper's rose, outer radius 2.3 cm
  const std::vector<double> ticks = axis.ticks();
  // 4.6 cm over ~6 ticks: a step of 1 cm, from -2 to 2.
  ASSERT_EQ(ticks.size(), 5u);
  EXPECT_NEAR(ticks.front(), -0.02, 1e-12);
  EXPECT_NEAR(ticks.back(), 0.02, 1e-12);
  EXPECT_EQ(axis.label(ticks.front()), "-2");
  EXPECT_EQ(axis.label(0.0), "0");
  EXPECT_DOUBLE_EQ(axis.toPixel(0.0, 100.0, 300.0), 200.0);
}

TEST(PlotAxis, FractionalStepsGetDecimals) {
  const PlotAxis axis(0.0, 1.2, 1.0);
  const std::vector<double> ticks = axis.ticks();
  EXPECT_NEAR(ticks[1], 0.2, 1e-12);
  EXPECT_EQ(axis.label(ticks[1]), "0.2");
}

TEST(PlotAxis, DegenerateAndEmptyRangesAreWidened) {
  DataRange single;
  single.add(0.5);
  single.add(std::numeric_limits<double>::quiet_NaN());
  const PlotAxis one = axisFor({}, single);
  EXPECT_LT(one.lo(), 0.5);
  EXPECT_GT(one.hi(), 0.5);
  const PlotAxis none = axisFor({}, DataRange{});
  EXPECT_LT(none.lo(), none.hi());
  AxisSpec fixed;
  fixed.min = 0.0;
  fixed.max = 35.0;
  const PlotAxis given = axisFor(fixed, single);
  EXPECT_EQ(given.lo(), 0.0);
  EXPECT_EQ(given.hi(), 35.0);
}

}  // namespace
}  // namespace hemiroll::report
