#include "engine/render/SceneGeometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hemiroll::render {
namespace {

TEST(SceneGeometryTest, TargetBandIsTheJudgedBoxClippedToTheFloor) {
  RenderScene s;
  s.targets.push_back({{-0.04, -0.04}, {0.004, 0.002}, false});
  s.targets.push_back({{0.1, 0.0}, {1e3, 0.01}, true});  // x free
  std::vector<Vertex> v;
  appendTargetFills(s, 0.5, v);
  ASSERT_EQ(v.size(), 12u);
  float lo[2] = {1e9f, 1e9f}, hi[2] = {-1e9f, -1e9f};
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], v[i].position[k]), hi[k] = std::max(hi[k], v[i].position[k]);
  EXPECT_FLOAT_EQ(lo[0], -0.044f);
  EXPECT_FLOAT_EQ(hi[0], -0.036f);
  EXPECT_FLOAT_EQ(lo[1], -0.042f);
  EXPECT_FLOAT_EQ(hi[1], -0.038f);
  EXPECT_FLOAT_EQ(v[6].position[0], -0.5f);  // the free band stops at the floor's edge
  EXPECT_EQ(v[6].color[3], kTargetFillInside.a);
}

// The pointer runs from the contact point (under the centre) to the target,
// ends in a head of two strokes, leaves out a free component, and is gone
// once the contact point is inside.
TEST(SceneGeometryTest, APointerRunsFromTheContactPointToTheTarget) {
  RenderScene s;
  s.centre = {0.01, 0.02, 0.04};
  s.targets.push_back({{-0.03, -0.01}, {0.004, 0.004}, false});
  std::vector<Vertex> v;
  appendTargetPointers(s, v);
  ASSERT_EQ(v.size(), 6u);
  EXPECT_FLOAT_EQ(v[0].position[0], 0.01f);
  EXPECT_FLOAT_EQ(v[0].position[1], 0.02f);
  EXPECT_FLOAT_EQ(v[1].position[0], -0.03f);
  EXPECT_FLOAT_EQ(v[1].position[1], -0.01f);
  // Both head strokes start at the tip and point back towards the contact point.
  for (int k : {3, 5}) {
    const double bx = v[k].position[0] - v[k - 1].position[0], by = v[k].position[1] - v[k - 1].position[1];
    EXPECT_GT(bx * 0.04 + by * 0.03, 0.0);  // along (0.04, 0.03), from the tip towards the start
    EXPECT_NEAR(std::hypot(bx, by), 0.006, 1e-6);  // min(0.3 * 5 cm, 6 mm)
  }
  // x free: the pointer goes along y only.
  s.targets[0].halfWidth[0] = 1e3;
  v.clear();
  appendTargetPointers(s, v);
  ASSERT_EQ(v.size(), 6u);
  EXPECT_FLOAT_EQ(v[1].position[0], 0.01f);
  // Inside: nothing.
  s.targets[0].inside = true;
  v.clear();
  appendTargetPointers(s, v);
  EXPECT_TRUE(v.empty());
}

TEST(SceneGeometryTest, TraceSegmentsFadeWithAge) {
  ContactTrace trace({.capacity = 8, .minSpacing = 0.0, .fadeTime = 10.0});
  for (int i = 0; i < 5; ++i) trace.push(0.01 * i, 0.0, 2.0 * i);
  std::vector<Vertex> v;
  appendTraceLines(trace, 8.0, v);
  ASSERT_EQ(v.size(), 8u);  // 4 segments, 2 vertices each
  EXPECT_FLOAT_EQ(v.front().color[3], 0.2f);  // the oldest point: 8 s old of 10
  EXPECT_FLOAT_EQ(v.back().color[3], 1.0f);
  for (std::size_t i = 1; i < v.size(); ++i) EXPECT_GE(v[i].color[3], v[i - 1].color[3]);
}

// Dashed: segments 0-1, 2-3, ... so that the trace stays visible along it;
// never more vertices than the renderer's room.
TEST(SceneGeometryTest, TheExamplePathIsDashedOnThePlane) {
  RenderScene s;
  for (int i = 0; i < 7; ++i) s.examplePath.push_back({0.001 * i, 0.002 * i});
  std::vector<Vertex> v;
  appendExamplePath(s, 1000, v);
  ASSERT_EQ(v.size(), 6u);  // 3 dashes out of 6 segments
  EXPECT_FLOAT_EQ(v[2].position[0], 0.002f);
  EXPECT_FLOAT_EQ(v[3].position[1], 0.006f);
  for (const Vertex& x : v) EXPECT_EQ(x.position[2], 0.0f);
  v.clear();
  appendExamplePath(s, 4, v);
  EXPECT_EQ(v.size(), 4u);
}

TEST(SceneGeometryTest, SpringCoilJoinsBothEndsAndStaysNearTheAxis) {
  const Vec3d a{0.0, 0.0, 0.04}, b{0.03, 0.01, 0.06};
  std::vector<Vertex> v;
  appendSpringCoil(a, b, 0.002, 8, v);
  ASSERT_FALSE(v.empty());
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(v.front().position[k], a[k], 1e-7);  // float positions
    EXPECT_NEAR(v.back().position[k], b[k], 1e-7);
  }
  v.clear();
  appendSpringCoil(a, a, 0.002, 8, v);  // zero length: nothing (no NaN direction)
  EXPECT_TRUE(v.empty());
}

TEST(SceneGeometryTest, GridHasDecimetreLinesFarAndCentimetreLinesNear) {
  const MeshData grid = makeFloorGrid(0.5, 0.2);
  EXPECT_EQ(grid.primitive, Primitive::Lines);
  // 11 decimetre lines (-50..50 cm) and 36 centimetre lines within 20 cm, both directions, 2 vertices each.
  ASSERT_EQ(grid.vertices.size(), std::size_t((11 + 36) * 4));
  int coarse = 0;
  for (std::size_t i = 0; i < grid.vertices.size(); i += 4) {
    const float x = grid.vertices[i].position[0];
    const float reach = std::abs(grid.vertices[i].position[1]);
    if (std::abs(std::remainder(x, 0.1f)) < 1e-4f) {
      ++coarse;
      EXPECT_GT(grid.vertices[i].color[3], 0.2f);
      EXPECT_FLOAT_EQ(reach, 0.5f);
    } else {
      EXPECT_LT(grid.vertices[i].color[3], 0.2f);
      EXPECT_LE(std::abs(x), 0.2f + 1e-6f);
      EXPECT_FLOAT_EQ(reach, 0.2f);
    }
  }
  EXPECT_EQ(coarse, 11);
}

TEST(SceneGeometryTest, ZonesFillAndOutline) {
  RenderScene s;
  s.forbidden.push_back({true, {0.05, 0.0}, 0.01, {}, {}});
  s.forbidden.push_back({false, {}, 0.0, {0.0, 0.0}, {0.02, 0.01}});
  std::vector<Vertex> fill, lines;
  appendZoneFills(s, fill);
  appendZoneOutlines(s, lines);
  EXPECT_EQ(fill.size(), std::size_t(3 * kCircleSegments + 6));
  EXPECT_EQ(lines.size(), std::size_t(2 * kCircleSegments + 8));
  for (std::size_t i = 1; i < 3 * kCircleSegments; i += 3) {
    const double r = std::hypot(fill[i].position[0] - 0.05, fill[i].position[1]);
    EXPECT_NEAR(r, 0.01, 1e-7);
  }
}

// The strain ring: flat at the centre's height, every vertex on the inner
// or the outer circle, two triangles a segment; nothing for a bad width.
TEST(SceneGeometryTest, AFlatRingLiesBetweenItsTwoRadiiAtTheCentresHeight) {
  std::vector<Vertex> out;
  appendFlatRing({0.01, -0.02, 0.05}, 0.004, 0.006, 48, Rgba{1, 0, 0, 1}, out);
  ASSERT_EQ(out.size(), 6u * 48u);
  for (const Vertex& v : out) {
    EXPECT_FLOAT_EQ(v.position[2], 0.05f);
    const double r = std::hypot(v.position[0] - 0.01, v.position[1] + 0.02);
    EXPECT_TRUE(std::abs(r - 0.004) < 1e-6 || std::abs(r - 0.006) < 1e-6) << r;
  }
  out.clear();
  appendFlatRing({0, 0, 0}, 0.006, 0.004, 48, Rgba{1, 0, 0, 1}, out);
  appendFlatRing({0, 0, 0}, -1.0, 0.004, 48, Rgba{1, 0, 0, 1}, out);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace hemiroll::render
