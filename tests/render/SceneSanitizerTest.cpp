#include "engine/render/SceneSanitizer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace hemiroll::render {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

RenderScene goodScene() {
  RenderScene s;
  s.centre = {0.01, 0.02, 0.04};
  s.orientation = {0, -1, 0, 1, 0, 0, 0, 0, 1};  // 90 degrees about z
  s.massPoint = {0.005, 0.0};
  s.showProxy = true;
  s.proxyPosition = {0.0, 0.0, 0.05};
  s.springOn = true;
  s.force = {1.0, 0.0, 0.0};
  s.targets.push_back({{-0.04, -0.04}, {0.004, 0.004}, false});
  s.forbidden.push_back({true, {0.05, 0.0}, 0.01, {}, {}});
  return s;
}

TEST(SceneSanitizerTest, AGoodSceneIsCopiedAsItIs) {
  SceneSanitizer sanitizer;
  RenderScene out;
  const RenderScene in = goodScene();
  EXPECT_TRUE(sanitizer.sanitize(in, out));
  EXPECT_EQ(out.centre, in.centre);
  EXPECT_EQ(out.orientation, in.orientation);
  EXPECT_EQ(out.massPoint, in.massPoint);
  EXPECT_EQ(out.force, in.force);
  EXPECT_TRUE(out.springOn);
  EXPECT_EQ(out.targets.size(), 1u);
  EXPECT_EQ(out.forbidden.size(), 1u);
}

TEST(SceneSanitizerTest, ANonFinitePoseFallsBackToTheLastGoodOneAsAWhole) {
  SceneSanitizer sanitizer;
  RenderScene out;
  const RenderScene good = goodScene();
  sanitizer.sanitize(good, out);
  RenderScene bad = good;
  bad.centre = {0.5, 0.5, 0.04};   // finite, but the orientation below is broken:
  bad.orientation[4] = kNaN;       // the whole pose must come from the last good frame
  EXPECT_FALSE(sanitizer.sanitize(bad, out));
  EXPECT_EQ(out.centre, good.centre);
  EXPECT_EQ(out.orientation, good.orientation);
}

TEST(SceneSanitizerTest, AMatrixThatIsNotARotationIsRejected) {
  SceneSanitizer sanitizer;
  RenderScene out;
  RenderScene sheared = goodScene();
  sheared.orientation = {1, 0.5, 0, 0, 1, 0, 0, 0, 1};
  EXPECT_FALSE(sanitizer.sanitize(sheared, out));
  EXPECT_FALSE(sanitizer.hasGoodPose());
  EXPECT_EQ(out.orientation, RenderScene{}.orientation);  // upright until a good pose arrives
}

TEST(SceneSanitizerTest, BadMarkersAreSkippedAndABadForceIsZero) {
  SceneSanitizer sanitizer;
  RenderScene out;
  RenderScene s = goodScene();
  s.force = {kNaN, 0, 0};
  s.proxyPosition = {0, std::numeric_limits<double>::infinity(), 0};
  s.targets.push_back({{kNaN, 0.0}, {0.004, 0.004}, false});
  s.targets.push_back({{0.0, 0.0}, {0.0, 0.004}, false});  // a zero tolerance band is no band
  s.forbidden.push_back({true, {0.0, 0.0}, kNaN, {}, {}});
  s.forbidden.push_back({false, {}, 0.0, {0.1, 0.1}, {0.0, 0.2}});  // min > max
  s.camera.zoom = kNaN;
  s.examplePath = {{0.0, 0.0}, {kNaN, 0.01}, {0.02, 0.0}};  // a bad point is left out, not drawn to the origin
  EXPECT_FALSE(sanitizer.sanitize(s, out));
  EXPECT_EQ(out.examplePath, (std::vector<Vec2d>{{0.0, 0.0}, {0.02, 0.0}}));
  EXPECT_EQ(out.force, (Vec3d{0, 0, 0}));
  EXPECT_FALSE(out.showProxy);
  EXPECT_FALSE(out.springOn);
  EXPECT_EQ(out.targets.size(), 1u);
  EXPECT_EQ(out.forbidden.size(), 1u);
  EXPECT_EQ(out.camera.zoom, 1.0);
}

// The strain ring goes with the proxy, and a NaN size or colour leaves it out.
TEST(SceneSanitizerTest, TheProxyRingNeedsTheProxyAndAFiniteSizeAndColour) {
  SceneSanitizer sanitizer;
  RenderScene out;
  RenderScene in = goodScene();
  in.showProxyRing = true;
  in.proxyRingRadius = 0.01;
  in.proxyRingColour = {1.0f, 0.5f, 0.0f, 1.0f};
  EXPECT_TRUE(sanitizer.sanitize(in, out));
  EXPECT_TRUE(out.showProxyRing);
  EXPECT_EQ(out.proxyRingRadius, 0.01);
  in.proxyRingRadius = kNaN;
  EXPECT_FALSE(sanitizer.sanitize(in, out));
  EXPECT_FALSE(out.showProxyRing);
  in.proxyRingRadius = 0.01;
  in.proxyRingColour[3] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(sanitizer.sanitize(in, out));
  EXPECT_FALSE(out.showProxyRing);
  in = goodScene();
  in.showProxyRing = true;
  in.proxyRingRadius = 0.01;
  in.showProxy = false;
  sanitizer.sanitize(in, out);
  EXPECT_FALSE(out.showProxyRing);
}

}  // namespace
}  // namespace hemiroll::render
