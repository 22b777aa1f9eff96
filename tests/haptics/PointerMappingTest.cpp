#include "engine/haptics/PointerMapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace hemiroll::haptics {
namespace {

PointerMappingDef def() {
  PointerMappingDef d;
  d.metresPerPixel = 0.001;
  d.wheelStep = 0.01;
  d.minHeight = -0.02;
  d.maxHeight = 0.03;
  d.reach = 0.08;
  return d;
}

TEST(PointerMappingTest, StartsAtTheOriginAndMotionRightIsXUpIsY) {
  PointerMapping m(def());
  EXPECT_EQ(m.position(), Vec3::Zero());
  m.moveBy(20.0, 0.0);
  EXPECT_NEAR(m.position().x(), 0.020, 1e-15);
  m.moveBy(0.0, -10.0);  // 10 px up the screen (pixel rows grow downwards)
  EXPECT_NEAR(m.position().y(), 0.010, 1e-15);
  m.moveBy(-20.0, 20.0);
  EXPECT_NEAR(m.position().x(), 0.0, 1e-15);
  EXPECT_NEAR(m.position().y(), -0.010, 1e-15);
}

// Where the proxy is depends on the motion only, not on where the pointer
// is in the window: the same strokes in any order end at the same place.
TEST(PointerMappingTest, ThePositionIsTheSumOfTheMotions) {
  PointerMapping a(def()), b(def());
  a.moveBy(3.0, 4.0);
  a.moveBy(-7.0, 1.0);
  b.moveBy(-7.0, 1.0);
  b.moveBy(3.0, 4.0);
  EXPECT_NEAR((a.position() - b.position()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(a.position().x(), -0.004, 1e-15);
  EXPECT_NEAR(a.position().y(), -0.005, 1e-15);
}

// An orbit camera turned by 90 degrees: screen right is device +y, so a
// stroke to the right moves the proxy along +y, and a stroke up along -x.
TEST(PointerMappingTest, ScreenYawTurnsTheStrokesWithTheCamera) {
  PointerMapping m(def());
  m.setScreenYaw(std::numbers::pi / 2.0);
  m.moveBy(10.0, 0.0);
  EXPECT_NEAR(m.position().x(), 0.0, 1e-15);
  EXPECT_NEAR(m.position().y(), 0.010, 1e-15);
  m.moveBy(0.0, -10.0);
  EXPECT_NEAR(m.position().x(), -0.010, 1e-15);
  m.setScreenYaw(std::nan(""));  // ignored
  m.moveBy(10.0, 0.0);
  EXPECT_NEAR(m.position().y(), 0.020, 1e-15);
}

TEST(PointerMappingTest, WheelStepsTheHeightWithinItsRange) {
  PointerMapping m(def());
  m.wheel(2.0);
  EXPECT_NEAR(m.position().z(), 0.02, 1e-15);
  m.wheel(5.0);
  EXPECT_EQ(m.height(), 0.03);
  m.wheel(-100.0);
  EXPECT_EQ(m.height(), -0.02);
  m.wheel(std::nan(""));
  EXPECT_EQ(m.height(), -0.02);
  m.setHeight(0.011);  // taking hold puts the proxy at the mass point's height
  EXPECT_EQ(m.height(), 0.011);
  m.setHeight(1.0);
  EXPECT_EQ(m.height(), 0.03);
  m.setHeight(std::nan(""));
  EXPECT_EQ(m.height(), 0.03);
}

TEST(PointerMappingTest, FarStrokesStayWithinReachInTheirDirection) {
  PointerMapping m(def());
  m.moveBy(3000.0, -4000.0);  // 5 m away along (3, 4)
  EXPECT_NEAR(std::hypot(m.position().x(), m.position().y()), 0.08, 1e-12);
  EXPECT_NEAR(m.position().x() / m.position().y(), 0.75, 1e-12);
  m.moveBy(std::nan(""), 1e308);
  m.moveBy(1e308, 1e308);  // a huge stroke ends at the reach
  EXPECT_TRUE(m.position().allFinite());
  m.moveTo(0.001, -0.002);
  EXPECT_EQ(m.position().x(), 0.001);
  EXPECT_EQ(m.position().y(), -0.002);
}

TEST(PointerMappingTest, InvalidDefinitionsNameTheField) {
  PointerMappingDef d = def();
  d.metresPerPixel = 0.0;
  try {
    PointerMapping m(d);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("metresPerPixel"), std::string::npos);
  }
  d = def();
  d.minHeight = 0.1;
  EXPECT_THROW(PointerMapping{d}, std::invalid_argument);
}

}  // namespace
}  // namespace hemiroll::haptics
