#include "engine/render/HemisphereMesh.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hemiroll::render {
namespace {

bool sameColour(const Vertex& v, Rgba c) {
  return v.color[0] == c.r && v.color[1] == c.g && v.color[2] == c.b && v.color[3] == c.a;
}

// Float vertices from double trigonometry: 1e-6 is a few float ulps at R = 1.
constexpr double kTol = 1e-6;

TEST(HemisphereMeshTest, ShellBelowTheFaceWithRadialNormalsFaceAtZeroFacingUp) {
  const HemisphereMeshDef def;
  const MeshData m = makeHemisphereMesh(def);
  EXPECT_EQ(m.primitive, Primitive::Triangles);
  // 6 vertices per quad: segments x rings on the shell, segments x 5 annuli on the face.
  ASSERT_EQ(m.vertices.size(), std::size_t(6 * (def.segments * def.rings + def.segments * 5)));
  int shell = 0, face = 0;
  for (const Vertex& v : m.vertices) {
    const double r = std::sqrt(v.position[0] * v.position[0] + v.position[1] * v.position[1] + v.position[2] * v.position[2]);
    const double n = std::sqrt(v.normal[0] * v.normal[0] + v.normal[1] * v.normal[1] + v.normal[2] * v.normal[2]);
    EXPECT_NEAR(n, 1.0, kTol);
    EXPECT_LE(v.position[2], kTol);
    if (v.normal[2] == 1.0f && v.position[2] == 0.0f) {
      ++face;
      EXPECT_LE(r, 1.0 + kTol);
    } else {
      ++shell;
      EXPECT_NEAR(r, 1.0, kTol);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(v.normal[k], v.position[k], kTol);  // smooth: normal = p / R
    }
  }
  EXPECT_EQ(shell, 6 * def.segments * def.rings);
  EXPECT_EQ(face, 6 * def.segments * 5);
}

TEST(HemisphereMeshTest, RedMarkingsAreAroundBodyPlusX) {
  const MeshData m = makeHemisphereMesh();
  int red = 0;
  for (std::size_t i = 0; i < m.vertices.size(); i += 3) {
    const Vertex& a = m.vertices[i];
    if (!sameColour(a, kMarkRed)) continue;
    ++red;
    // The triangle's centroid lies on the +x side, within the red sector.
    double cx = 0, cy = 0;
    for (int k = 0; k < 3; ++k) cx += m.vertices[i + k].position[0], cy += m.vertices[i + k].position[1];
    EXPECT_GT(cx, 0.0);
    EXPECT_LT(std::abs(std::atan2(cy, cx)), M_PI / 8.0 + 1e-9);  // one stripe of eight is 45 degrees wide
  }
  EXPECT_GT(red, 0);
}

TEST(HemisphereMeshTest, TheFaceRingIsAtItsRadius) {
  const MeshData m = makeHemisphereMesh();
  int ring = 0;
  for (const Vertex& v : m.vertices) {
    if (!sameColour(v, kFaceRing)) continue;
    ++ring;
    const double r = std::hypot(v.position[0], v.position[1]);
    EXPECT_NEAR(std::abs(r - kFaceRingRadius), kFaceRingHalfWidth, kTol);  // on one of the band's two edges
  }
  EXPECT_GT(ring, 0);
}

TEST(HemisphereMeshTest, RejectsStripesThatDoNotDivideTheSegments) {
  EXPECT_THROW(makeHemisphereMesh({.radius = 1.0, .segments = 50, .rings = 8, .stripes = 8}), std::invalid_argument);
  EXPECT_THROW(makeHemisphereMesh({.radius = 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace hemiroll::render
