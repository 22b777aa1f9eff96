#include "engine/render/MeshLoader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/support/TempDirectory.h"

namespace hemiroll::render {
namespace {

TEST(MeshLoaderTest, LoadsTheShippedProxyMeshScaledToTheUnitSphere) {
  const LoadedMesh m = loadMeshFile(std::string(HEMIROLL_SOURCE_DIR) + "/assets/meshes/proxy.obj");
  ASSERT_TRUE(m.mesh) << m.error;
  EXPECT_EQ(m.mesh->vertices.size() % 3, 0u);
  double largest = 0.0;
  for (const Vertex& v : m.mesh->vertices)
    largest = std::max(largest, std::sqrt(double(v.position[0]) * v.position[0] + double(v.position[1]) * v.position[1] +
                                          double(v.position[2]) * v.position[2]));
  EXPECT_NEAR(largest, 1.0, 1e-6);  // float positions
}

TEST(MeshLoaderTest, LoadsAGltfFile) {
  test::TempDirectory dir;
  // One triangle in a minimal glTF 2.0 with an embedded buffer (3 float3 positions).
  const std::string gltf = R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"scene":0,"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
"bufferViews":[{"buffer":0,"byteLength":36}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]})";
  const LoadedMesh m = loadMeshFile(dir.write("tri.gltf", gltf));
  ASSERT_TRUE(m.mesh) << m.error;
  EXPECT_EQ(m.mesh->vertices.size(), 3u);
}

// The shipped scenery: the glTF cone stands up (glTF's y up turned to the
// engine's z up: its apex, the one vertex on the axis at the top, is the
// highest point), and the OBJ flag (z up as written) has its pole along z.
TEST(MeshLoaderTest, ShippedSceneryStandsUp) {
  const LoadedMesh cone = loadMeshFile(std::string(HEMIROLL_SOURCE_DIR) + "/assets/meshes/cone.gltf");
  ASSERT_TRUE(cone.mesh) << cone.error;
  float zMax = -1e9f, zMin = 1e9f, xAtTop = 1e9f, yAtTop = 1e9f;
  for (const Vertex& v : cone.mesh->vertices) {
    zMin = std::min(zMin, v.position[2]);
    if (v.position[2] > zMax) zMax = v.position[2], xAtTop = v.position[0], yAtTop = v.position[1];
  }
  EXPECT_NEAR(xAtTop, 0.0f, 1e-6f);  // the apex is on the vertical axis
  EXPECT_NEAR(yAtTop, 0.0f, 1e-6f);
  EXPECT_GT(zMax - zMin, 1.5f);  // tall along z (scaled to the unit sphere: height/radius 1.2/0.5)
  const std::size_t coloured = std::count_if(cone.mesh->vertices.begin(), cone.mesh->vertices.end(),
                                             [](const Vertex& v) { return v.color[0] > 0.9f && v.color[2] < 0.2f; });
  EXPECT_GT(coloured, 0u);  // its own vertex colours (orange) came through

  const LoadedMesh flag = loadMeshFile(std::string(HEMIROLL_SOURCE_DIR) + "/assets/meshes/flag.obj");
  ASSERT_TRUE(flag.mesh) << flag.error;
  float flagLo = 1e9f, flagHi = -1e9f;
  for (const Vertex& v : flag.mesh->vertices) flagLo = std::min(flagLo, v.position[2]), flagHi = std::max(flagHi, v.position[2]);
  EXPECT_GT(flagHi - flagLo, 1.5f);  // the pole's height dominates the unit sphere
}

TEST(MeshLoaderTest, MissingOrCorruptFilesGiveAMessageNamingTheFile) {
  test::TempDirectory dir;
  const std::string missing = (dir.path() / "nope.obj").string();
  LoadedMesh m = loadMeshFile(missing);
  EXPECT_FALSE(m.mesh);
  EXPECT_NE(m.error.find(missing), std::string::npos) << m.error;

  const std::string corrupt = dir.write("broken.glb", std::string("glTF\x02\0\0\0garbage", 15));
  m = loadMeshFile(corrupt);
  EXPECT_FALSE(m.mesh);
  EXPECT_NE(m.error.find(corrupt), std::string::npos) << m.error;

  const std::string empty = dir.write("empty.obj", "# nothing here\n");
  m = loadMeshFile(empty);
  EXPECT_FALSE(m.mesh);
  EXPECT_NE(m.error.find(empty), std::string::npos) << m.error;
}

}  // namespace
}  // namespace hemiroll::render
