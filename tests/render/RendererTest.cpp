// Runs under Xvfb with Mesa's llvmpipe (tests/render/CMakeLists.txt): renders
// known scenes offscreen, compares them with tests/render/reference/*.png
// (support/ImageCompare.h says how closely and why) and probes pixels where
// the camera's projection says a marker must be.
#include "engine/render/Renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "engine/physics/Orientation.h"
#include "engine/render/ContactTrace.h"
#include "engine/render/Framebuffer.h"
#include "engine/render/RenderError.h"
#include "tests/support/AllocationCounter.h"
#include "tests/render/support/GlTestContext.h"
#include "tests/render/support/ImageCompare.h"

namespace hemiroll::render {
namespace {

constexpr int kW = 320, kH = 240;
constexpr double kR = 0.04;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

Mat3d orientation(double u_o, double v_o, double psi) {
  const physics::Orientation o = physics::makeOrientation(u_o, v_o, psi);
  Mat3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[3 * i + j] = o.R(i, j);
  return m;
}

RenderScene uprightAt(double x, double y) {
  RenderScene s;
  s.radius = kR;
  s.centre = {x, y, kR};
  return s;
}

// The paper's task mid-trial: tilted and turned, proxy pulling, target, zone, trace.
RenderScene taskScene(const ContactTrace& trace, CameraMode mode) {
  RenderScene s = uprightAt(0.01, -0.01);
  s.orientation = orientation(0.3, 0.2, 0.5);
  s.massPoint = {0.01, 0.005};
  s.showProxy = true;
  s.proxyPosition = {0.03, -0.02, 0.07};
  s.springOn = true;
  s.force = {1.0, 0.5, 2.0};
  s.targets.push_back({{-0.04, -0.04}, {0.004, 0.004}, false});
  s.forbidden.push_back({true, {0.06, 0.04}, 0.015, {}, {}});
  s.trace = &trace;
  s.time = 10.0;
  s.camera.mode = mode;
  return s;
}

void fillTrace(ContactTrace& trace) {
  for (int i = 0; i <= 100; ++i) {
    const double a = 0.12 * i, r = 0.0008 * (100 - i);  // a spiral from 8 cm out to the contact point
    trace.push(0.01 + r * std::cos(a), -0.01 + r * std::sin(a), 0.1 * i);
  }
}

class RendererTest : public ::testing::Test {
 protected:
  void SetUp() override {
    test::useGlContext();
    RendererDef def;
    def.assetsDir = std::string(HEMIROLL_SOURCE_DIR) + "/assets";
    renderer_ = std::make_unique<Renderer>(def);
    target_ = std::make_unique<Framebuffer>(kW, kH);
  }
  Image draw(const RenderScene& scene) {
    target_->bind();
    renderer_->render(scene, kW, kH);
    return target_->read();
  }
  // Does any pixel within `radius` of the projection of `world` satisfy `test`?
  bool near(const Image& image, const Vec3d& world, int radius, const std::function<bool(const std::uint8_t*)>& test) {
    const PixelPoint p = projectToPixel(renderer_->camera(), world, kW, kH);
    EXPECT_TRUE(p.visible);
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) {
        const int x = int(std::floor(p.x)) + dx, y = int(std::floor(p.y)) + dy;
        if (x >= 0 && y >= 0 && x < kW && y < kH && test(image.pixel(x, y))) return true;
      }
    return false;
  }
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<Framebuffer> target_;
};

bool greenish(const std::uint8_t* p) { return p[1] > p[0] + 25 && p[1] > p[2] + 15; }
bool red(const std::uint8_t* p) { return p[0] > 100 && p[0] > p[1] + 60 && p[0] > p[2] + 60; }
bool orange(const std::uint8_t* p) { return p[0] > 180 && p[1] > 60 && p[1] < 170 && p[2] < 90; }

TEST_F(RendererTest, AllAssetsLoad) { EXPECT_TRUE(renderer_->notes().empty()) << renderer_->notes().front(); }

TEST_F(RendererTest, TaskScenesMatchTheirReferences) {
  ContactTrace trace;
  fillTrace(trace);
  EXPECT_TRUE(test::matchesReference(draw(taskScene(trace, CameraMode::Follow)), "task_follow"));
  EXPECT_TRUE(test::matchesReference(draw(taskScene(trace, CameraMode::Top)), "task_top"));
  RenderScene orbit = taskScene(trace, CameraMode::Orbit);
  orbit.camera.yaw = 0.8;
  orbit.camera.pitch = 0.4;
  orbit.camera.zoom = 1.5;
  EXPECT_TRUE(test::matchesReference(draw(orbit), "task_orbit"));
}

TEST_F(RendererTest, TheComparisonSeesASmallTurn) {
  // The tolerance must not hide a real change: the hemisphere turned by 0.3 rad.
  ContactTrace trace;
  RenderScene a = taskScene(trace, CameraMode::Follow), b = a;
  b.orientation = orientation(0.3, 0.2, 0.8);
  EXPECT_FALSE(test::compareImages(draw(a), draw(b)).matches());
}

TEST_F(RendererTest, TheTargetBandIsWhereTheCameraProjectsIt) {
  for (CameraMode mode : {CameraMode::Top, CameraMode::Follow}) {
    RenderScene s = uprightAt(0.0, 0.0);
    s.camera.mode = mode;
    s.targets.push_back({{-0.04, -0.04}, {0.004, 0.004}, false});
    const Image image = draw(s);
    // Inside the band, away from the cross at its centre; and well outside it.
    EXPECT_TRUE(near(image, {-0.0375, -0.0375, 0.0}, 0, greenish));
    EXPECT_FALSE(near(image, {-0.05, -0.05, 0.0}, 1, greenish));
    s.targets.clear();
    EXPECT_FALSE(near(draw(s), {-0.0375, -0.0375, 0.0}, 0, greenish));  // green came from the target
  }
}

TEST_F(RendererTest, TheTraceIsDrawnAlongItsPoints) {
  ContactTrace trace;
  for (int i = 0; i <= 40; ++i) trace.push(0.05 + 0.001 * i, 0.03, 9.0 + 0.01 * i);  // 4 cm long, recent
  RenderScene s = uprightAt(0.0, 0.0);
  s.camera.mode = CameraMode::Top;
  s.time = 10.0;
  EXPECT_FALSE(near(draw(s), {0.07, 0.03, 0.0}, 1, orange));
  s.trace = &trace;
  const Image image = draw(s);
  for (double x : {0.055, 0.07, 0.085}) EXPECT_TRUE(near(image, {x, 0.03, 0.0}, 1, orange)) << x;
  EXPECT_FALSE(near(image, {0.07, 0.045, 0.0}, 1, orange));
}

TEST_F(RendererTest, FaceMarkingsTurnWithPsi) {
  // Looking down on the upright face: the red stripe runs from the centre along body +x.
  const auto stripePoint = [](double psi) {
    const physics::Orientation o = physics::makeOrientation(0.0, 0.0, psi);
    const physics::Vec3 p = physics::Vec3(0, 0, kR) + o.R * physics::Vec3(0.8 * kR, 0.0, 0.0);
    return Vec3d{p.x(), p.y(), p.z()};
  };
  RenderScene s = uprightAt(0.0, 0.0);
  s.camera.mode = CameraMode::Top;
  s.camera.zoom = 3.0;
  const Image turned0 = draw(s);
  EXPECT_TRUE(near(turned0, stripePoint(0.0), 1, red));
  EXPECT_FALSE(near(turned0, stripePoint(M_PI / 2), 1, red));
  s.orientation = orientation(0.0, 0.0, M_PI / 2);
  const Image turned90 = draw(s);
  EXPECT_TRUE(near(turned90, stripePoint(M_PI / 2), 1, red));
  EXPECT_FALSE(near(turned90, stripePoint(0.0), 1, red));
}

TEST_F(RendererTest, SkyAboveTheHorizonFloorBelow) {
  RenderScene s = uprightAt(0.0, 0.0);
  s.camera.mode = CameraMode::Orbit;
  s.camera.pitch = 0.1;  // eye low: the horizon is 0.1 rad above the view's centre
  const Image image = draw(s);
  // The horizon's row: tan(0.1) / tan(fovY / 2) of the half-height above the centre.
  const double horizon = kH / 2.0 * (1.0 - std::tan(0.1) / std::tan(s.camera.fovY / 2.0));
  const auto blueish = [](const std::uint8_t* p) { return p[2] > p[0] + 25; };
  EXPECT_TRUE(blueish(image.pixel(5, int(horizon) - 3)));
  EXPECT_FALSE(blueish(image.pixel(5, int(horizon) + 3)));
  s.camera.pitch = 0.6;  // the horizon above the frame: no sky at the top
  EXPECT_FALSE(blueish(draw(s).pixel(5, 0)));
}

TEST_F(RendererTest, NonFiniteScenesDrawTheLastGoodPoseAndNoBadMarkers) {
  RenderScene good = uprightAt(0.01, 0.0);
  good.orientation = orientation(0.2, -0.1, 1.0);
  const Image before = draw(good);
  EXPECT_TRUE(renderer_->lastSceneClean());

  ContactTrace trace;
  trace.push(kNaN, 0.0, 0.0);
  RenderScene bad = good;
  bad.centre[2] = kNaN;
  bad.orientation[0] = std::numeric_limits<double>::infinity();
  bad.massPoint = {kNaN, kNaN};
  bad.showProxy = true;
  bad.proxyPosition = {kNaN, 0, 0};
  bad.springOn = true;
  bad.force = {kNaN, kNaN, kNaN};
  bad.targets.push_back({{kNaN, 0.0}, {0.004, 0.004}, false});
  bad.forbidden.push_back({true, {0.0, 0.0}, kNaN, {}, {}});
  bad.trace = &trace;
  bad.time = kNaN;
  bad.camera.zoom = kNaN;
  const Image after = draw(bad);
  EXPECT_FALSE(renderer_->lastSceneClean());
  const test::ImageDifference d = test::compareImages(before, after);
  EXPECT_EQ(d.differingFraction, 0.0) << "max channel difference " << d.maxChannelDifference;
}

// The ghost is drawn where its pose says, translucent (the floor shows
// through: the pixel is neither the floor nor an opaque body), and a ghost
// with a bad pose is left out rather than drawn anywhere.
TEST_F(RendererTest, TheGhostIsDrawnTranslucentWhereItsPoseSays) {
  RenderScene s = uprightAt(0.0, 0.0);
  s.camera.mode = CameraMode::Top;
  const Vec3d ghostTop{0.05, 0.0, kR};  // its face centre, seen from above
  const Image without = draw(s);
  s.ghost.shown = true;
  s.ghost.centre = {0.05, 0.0, kR};
  const Image with = draw(s);
  const PixelPoint p = projectToPixel(renderer_->camera(), ghostTop, kW, kH);
  ASSERT_TRUE(p.visible);
  const std::uint8_t* before = without.pixel(int(p.x), int(p.y));
  const std::uint8_t* after = with.pixel(int(p.x), int(p.y));
  EXPECT_NE(std::memcmp(before, after, 3), 0) << "nothing drawn at the ghost";
  // Translucent blue over the floor: bluer than the floor, yet not the tint itself.
  EXPECT_GT(int(after[2]) - int(after[0]), int(before[2]) - int(before[0]));
  EXPECT_GT(after[0], 60);
  // The live hemisphere at the origin is drawn as before.
  const PixelPoint live = projectToPixel(renderer_->camera(), {0.0, 0.0, kR}, kW, kH);
  EXPECT_EQ(std::memcmp(without.pixel(int(live.x), int(live.y)), with.pixel(int(live.x), int(live.y)), 3), 0);

  s.ghost.orientation[0] = kNaN;
  const Image bad = draw(s);
  EXPECT_FALSE(renderer_->lastSceneClean());
  EXPECT_EQ(test::compareImages(without, bad).differingFraction, 0.0);
}

// Every replayed attempt starts with the ghost where the player's hemisphere
// is, and a tick apart they differ by less than a micrometre: the ghost must
// then be hidden by it, pixel for pixel, not speckle through where the
// nearly equal depths pass and fail the test by rounding.
TEST_F(RendererTest, AGhostInThePlayersPoseNeverSpecklesThroughIt) {
  for (const CameraMode mode : {CameraMode::Follow, CameraMode::Orbit, CameraMode::Top}) {
    RenderScene s = uprightAt(0.01, -0.01);
    s.orientation = orientation(0.3, 0.2, 0.5);
    s.massPoint = {0.01, 0.005};
    s.camera.mode = mode;
    const Image without = draw(s);
    s.ghost.shown = true;
    s.ghost.centre = {s.centre[0] + 3e-7, s.centre[1] - 2e-7, s.centre[2] + 1e-7};
    s.ghost.orientation = orientation(0.3 + 1e-6, 0.2, 0.5);
    s.ghost.massPoint = s.massPoint;
    const Image with = draw(s);
    const test::ImageDifference d = test::compareImages(without, with);
    EXPECT_EQ(d.differingFraction, 0.0) << "camera " << int(mode) << ": max channel difference "
                                        << d.maxChannelDifference;
  }
}

TEST_F(RendererTest, MissingAssetsFallBackToBuiltInsThatDrawTheSame) {
  RendererDef def;
  def.assetsDir = "/nonexistent-hemiroll-assets";
  Renderer fallback(def);
  ASSERT_EQ(fallback.notes().size(), 2u);  // the shaders and the proxy mesh
  EXPECT_NE(fallback.notes()[0].find("/nonexistent-hemiroll-assets/shaders/scene.vert"), std::string::npos)
      << fallback.notes()[0];
  EXPECT_NE(fallback.notes()[1].find("proxy.obj"), std::string::npos) << fallback.notes()[1];
  RenderScene s = uprightAt(0.0, 0.0);
  const Image fromFiles = draw(s);
  target_->bind();
  fallback.render(s, kW, kH);
  EXPECT_TRUE(test::compareImages(fromFiles, target_->read()).matches());  // the built-ins are the files' copies
}

TEST_F(RendererTest, AWarmFrameAllocatesNothing) {
  ContactTrace trace;
  fillTrace(trace);
  const RenderScene scene = taskScene(trace, CameraMode::Follow);
  target_->bind();
  renderer_->render(scene, kW, kH);  // warm: the scratch vectors reach their sizes
  ASSERT_TRUE(test::allocationCounterWorks());
  test::AllocationCounter counter;
  for (int i = 0; i < 3; ++i) renderer_->render(scene, kW, kH);
  EXPECT_EQ(counter.count(), 0);
}

TEST_F(RendererTest, ABadImageSizeIsAnError) {
  EXPECT_THROW(Framebuffer(0, 10), RenderError);
  EXPECT_THROW(Framebuffer(1 << 20, 10), RenderError);
}

}  // namespace
}  // namespace hemiroll::render
