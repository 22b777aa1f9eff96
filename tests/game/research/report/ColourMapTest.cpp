// game/research/report ColourMap: the maps' ends, middle, clamping.

#include <gtest/gtest.h>

#include <limits>

#include "game/research/report/ColourMap.h"

namespace hemiroll::report {
namespace {

TEST(ColourMap, EndsMiddleAndClamping) {
  EXPECT_EQ(colourAt(ColourMap::Viridis, 0.0), "#440154");
  EXPECT_EQ(colourAt(ColourMap::Viridis, 1.0), "#fde725");
  EXPECT_EQ(colourAt(ColourMap::Viridis, 0.5), "#21918c");
  EXPECT_EQ(colourAt(ColourMap::Viridis, -3.0), "#440154");
  EXPECT_EQ(colourAt(ColourMap::Viridis, 7.0), "#fde725");
  EXPECT_EQ(colourAt(ColourMap::Diverging, 0.5), "#f7f7f7");
  EXPECT_EQ(colourAt(ColourMap::Diverging, std::numeric_limits<double>::quiet_NaN()), "#f7f7f7");
}

}  // namespace
}  // namespace hemiroll::report
