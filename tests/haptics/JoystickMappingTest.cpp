#include "engine/haptics/JoystickMapping.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hemiroll::haptics {
namespace {

TEST(JoystickMappingTest, DeadZoneThenContinuousRescale) {
  EXPECT_EQ(axisToUnit(0, 0.1), 0.0);
  EXPECT_EQ(axisToUnit(3000, 0.1), 0.0);   // 9 % deflection: inside the dead zone
  EXPECT_EQ(axisToUnit(-3000, 0.1), 0.0);
  EXPECT_EQ(axisToUnit(32767, 0.1), 1.0);
  EXPECT_EQ(axisToUnit(-32768, 0.1), -1.0);  // the extra negative count is clamped
  // Just past the edge the output is just above zero (no jump): 10.01 % -> 0.011 %.
  EXPECT_NEAR(axisToUnit(static_cast<std::int16_t>(0.1001 * 32767), 0.1), 0.0001 / 0.9, 1e-4);
  EXPECT_NEAR(axisToUnit(16384, 0.0), 0.5, 1e-4);
}

TEST(JoystickMappingTest, AxesToMetresWithinReach) {
  JoystickMappingDef d;
  d.reach = 0.05;
  d.deadZone = 0.0;
  d.centre = {0.0, 0.0, 0.04};
  const std::int16_t pushedRightAndAway[2] = {32767, -32767};
  const Vec3 p = axesToPosition(d, pushedRightAndAway, 2);
  EXPECT_NEAR(p.x(), 0.05, 1e-15);
  EXPECT_NEAR(p.y(), 0.05, 1e-15);  // away from the user is +y
  EXPECT_EQ(p.z(), 0.04);
  d.axisZ = 2;  // no third axis present: read as centred
  EXPECT_EQ(axesToPosition(d, pushedRightAndAway, 2).z(), 0.04);
  const std::int16_t withThrottle[3] = {0, 0, -32767};
  EXPECT_NEAR(axesToPosition(d, withThrottle, 3).z(), 0.09, 1e-15);
}

TEST(JoystickMappingTest, ForceLevelIsProportionalAndClampedAtMaxForce) {
  EXPECT_EQ(forceToConstantEffect(Vec3(1.0, 0.0, 0.0), 2.0).level, 16384);  // half of 32767, rounded
  EXPECT_EQ(forceToConstantEffect(Vec3(2.0, 0.0, 0.0), 2.0).level, 32767);
  EXPECT_EQ(forceToConstantEffect(Vec3(300.0, 400.0, 0.0), 2.0).level, 32767);
  EXPECT_EQ(forceToConstantEffect(Vec3(0.0, 0.0, 5.0), 2.0).level, 0);  // vertical: not renderable
  EXPECT_EQ(forceToConstantEffect(Vec3(std::nan(""), 1.0, 0.0), 2.0).level, 0);
  EXPECT_EQ(forceToConstantEffect(Vec3(1.0, 0.0, 0.0), 0.0).level, 0);
  EXPECT_EQ(forceToConstantEffect(Vec3(1e308, 1e308, 0.0), 2.0).level, 32767);  // hypot does not overflow
}

TEST(JoystickMappingTest, DirectionIsWhereTheForceComesFrom) {
  // Pushing the stick away (+y) comes from the south, SDL (0, +1).
  EXPECT_EQ(forceToConstantEffect(Vec3(0.0, 1.0, 0.0), 2.0).direction, (std::array<std::int32_t, 3>{0, 10000, 0}));
  // Pushing it right (+x) comes from the west, SDL (-1, 0).
  EXPECT_EQ(forceToConstantEffect(Vec3(1.0, 0.0, 0.0), 2.0).direction, (std::array<std::int32_t, 3>{-10000, 0, 0}));
  const auto d = forceToConstantEffect(Vec3(-0.3, -0.4, 0.0), 2.0).direction;
  EXPECT_EQ(d[0], 6000);
  EXPECT_EQ(d[1], -8000);
}

}  // namespace
}  // namespace hemiroll::haptics
