#include "engine/render/Camera.h"

#include <gtest/gtest.h>

namespace hemiroll::render {
namespace {

constexpr int kW = 640, kH = 480;
// Float matrices: positions agree to ~1e-6 relative; 1e-3 px is far below a pixel.
constexpr double kPx = 1e-3;

CameraView viewOf(CameraMode mode, double zoom = 1.0, const Vec3d& focus = {0.01, -0.02, 0.04}) {
  CameraDef def;
  def.mode = mode;
  def.zoom = zoom;
  return makeCameraView(def, focus, 0.04, double(kW) / kH);
}

TEST(CameraTest, EveryModeLooksAtTheFocus) {
  for (CameraMode mode : {CameraMode::Follow, CameraMode::Orbit, CameraMode::Top}) {
    const Vec3d focus{0.01, -0.02, 0.04};
    const PixelPoint p = projectToPixel(viewOf(mode), focus, kW, kH);
    EXPECT_TRUE(p.visible);
    EXPECT_NEAR(p.x, kW / 2.0, kPx);
    EXPECT_NEAR(p.y, kH / 2.0, kPx);
  }
}

TEST(CameraTest, FollowAndTopAgreeWithThePointerMapping) {
  // Screen right = +x; screen up = +y (PointerMapping moves the proxy so).
  for (CameraMode mode : {CameraMode::Follow, CameraMode::Top}) {
    const CameraView v = viewOf(mode);
    const PixelPoint centre = projectToPixel(v, {0.01, -0.02, 0.04}, kW, kH);
    const PixelPoint right = projectToPixel(v, {0.03, -0.02, 0.04}, kW, kH);
    const PixelPoint away = projectToPixel(v, {0.01, 0.0, 0.04}, kW, kH);
    EXPECT_GT(right.x, centre.x + 10);
    EXPECT_NEAR(right.y, centre.y, 1.0);
    EXPECT_LT(away.y, centre.y - 5);
  }
}

TEST(CameraTest, ZoomTwoDoublesOffsetsInTheTopView) {
  // Looking straight down, an offset in the focus plane scales exactly with 1 / distance.
  const Vec3d off{0.03, -0.02, 0.04};
  const PixelPoint a = projectToPixel(viewOf(CameraMode::Top, 1.0), off, kW, kH);
  const PixelPoint b = projectToPixel(viewOf(CameraMode::Top, 2.0), off, kW, kH);
  EXPECT_NEAR((b.x - kW / 2.0) / (a.x - kW / 2.0), 2.0, 1e-4);
}

TEST(CameraTest, AspectKeepsTheVerticalScale) {
  CameraDef def;
  def.mode = CameraMode::Top;
  const Vec3d focus{0, 0, 0.04}, up{0, 0.01, 0.04};
  const PixelPoint narrow = projectToPixel(makeCameraView(def, focus, 0.04, 1.0), up, 480, 480);
  const PixelPoint wide = projectToPixel(makeCameraView(def, focus, 0.04, 2.0), up, 960, 480);
  EXPECT_NEAR(narrow.y, wide.y, kPx);
}

TEST(CameraTest, PointsBehindTheEyeAreNotVisible) {
  const CameraView v = viewOf(CameraMode::Top);
  const Vec3d above{0.01, -0.02, double(v.eye.z()) + 1.0};
  EXPECT_FALSE(projectToPixel(v, above, kW, kH).visible);
}

TEST(CameraTest, OrbitPitchIsKeptAboveTheFloor) {
  CameraDef def;
  def.mode = CameraMode::Orbit;
  def.pitch = -1.0;
  const CameraView v = makeCameraView(def, {0, 0, 0.04}, 0.04, 1.0);
  EXPECT_GT(v.eye.z(), 0.04f);
}

}  // namespace
}  // namespace hemiroll::render
