#include "engine/haptics/EngagementRamp.h"

#include <gtest/gtest.h>

namespace hemiroll::haptics {
namespace {

constexpr double kDt = 0.001;

TEST(EngagementRampTest, EngagesOnlyWhenTheProxyComesWithinTheDistance) {
  EngagementRamp ramp({0.01, 1.0});
  ramp.update(kDt, 0.0);
  EXPECT_EQ(ramp.state(), Engagement::Disengaged);  // not asked: being near is not enough
  ramp.engage();
  for (int i = 0; i < 100; ++i) ramp.update(kDt, 0.0101);
  EXPECT_EQ(ramp.state(), Engagement::Armed);
  EXPECT_EQ(ramp.scale(), 0.0);
  EXPECT_FALSE(ramp.coupled());
  ramp.update(kDt, 0.0099);
  EXPECT_EQ(ramp.state(), Engagement::Engaged);
  EXPECT_TRUE(ramp.coupled());
}

TEST(EngagementRampTest, RampsInOverTheRampTimeAndOutAgain) {
  EngagementRamp ramp({0.01, 1.0});
  ramp.engage();
  ramp.update(kDt, 0.0);  // engages
  double previous = ramp.scale();
  for (int i = 0; i < 999; ++i) {
    ramp.update(kDt, 0.0);
    ASSERT_GE(ramp.scale(), previous);
    ASSERT_LE(ramp.scale() - previous, kDt / 1.0 + 1e-15);  // slope 1/rampTime
    previous = ramp.scale();
  }
  EXPECT_LT(ramp.scale(), 1.0);  // 999 steps of 1 ms: not yet there (summation error is ~1e-13)
  EXPECT_GT(ramp.scale(), 0.99);
  ramp.update(kDt, 0.0);
  ramp.update(kDt, 0.0);
  EXPECT_EQ(ramp.scale(), 1.0);
  ramp.disengage();
  EXPECT_EQ(ramp.state(), Engagement::RampingOut);
  ramp.update(kDt, 1.0);  // far away: the fade-out does not care
  EXPECT_LT(ramp.scale(), 1.0);
  EXPECT_TRUE(ramp.coupled());
  for (int i = 0; i < 1100 && ramp.state() != Engagement::Disengaged; ++i) ramp.update(kDt, 1.0);
  EXPECT_EQ(ramp.state(), Engagement::Disengaged);
  EXPECT_EQ(ramp.scale(), 0.0);
}

TEST(EngagementRampTest, DropNowRemovesTheForceAtOnce) {
  EngagementRamp ramp({0.01, 0.1});
  ramp.engage();
  for (int i = 0; i < 200; ++i) ramp.update(kDt, 0.0);
  EXPECT_EQ(ramp.scale(), 1.0);
  ramp.dropNow();
  EXPECT_EQ(ramp.scale(), 0.0);
  EXPECT_EQ(ramp.state(), Engagement::Disengaged);
}

}  // namespace
}  // namespace hemiroll::haptics
