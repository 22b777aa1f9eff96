#include "engine/haptics/PointerMapping.h"

#include <gtest/gtest.h>

namespace hemiroll::haptics {
namespace {

PointerMappingDef def() {
  PointerMappingDef d;
  d.metresPerPixel = 0.001;
  d.centreX = 100.0;
  d.centreY = 50.0;
  d.wheelStep = 0.01;
  d.minHeight = -0.02;
  d.maxHeight = 0.03;
  d.reach = 0.08;
  return d;
}

TEST(PointerMappingTest, CentreIsTheOriginRightIsXUpIsY) {
  const PointerMapping m(def());
  EXPECT_EQ(m.toMetres(100.0, 50.0), Vec3::Zero());
  EXPECT_NEAR(m.toMetres(120.0, 50.0).x(), 0.020, 1e-15);
  EXPECT_NEAR(m.toMetres(100.0, 40.0).y(), 0.010, 1e-15);  // 10 px up the screen
  EXPECT_NEAR(m.toMetres(100.0, 60.0).y(), -0.010, 1e-15);
}

TEST(PointerMappingTest, WheelStepsTheHeightWithinItsRange) {
  PointerMapping m(def());
  m.wheel(2.0);
  EXPECT_NEAR(m.toMetres(100.0, 50.0).z(), 0.02, 1e-15);
  m.wheel(5.0);
  EXPECT_EQ(m.height(), 0.03);
  m.wheel(-100.0);
  EXPECT_EQ(m.height(), -0.02);
  m.wheel(std::nan(""));
  EXPECT_EQ(m.height(), -0.02);
}

TEST(PointerMappingTest, FarPointersStayWithinReachInTheirDirection) {
  const PointerMapping m(def());
  const Vec3 p = m.toMetres(100.0 + 3000.0, 50.0 - 4000.0);  // 5 m away along (3, 4)
  EXPECT_NEAR(std::hypot(p.x(), p.y()), 0.08, 1e-12);
  EXPECT_NEAR(p.x() / p.y(), 0.75, 1e-12);
  EXPECT_TRUE(m.toMetres(std::nan(""), 1e308).allFinite());
}

TEST(PointerMappingTest, ResizeMovesTheCentre) {
  PointerMapping m(def());
  m.setCentre(400.0, 300.0);
  EXPECT_EQ(m.toMetres(400.0, 300.0), Vec3::Zero());
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
