// Runs under Xvfb with Mesa's llvmpipe (tests/render/CMakeLists.txt).
#include "engine/render/ShaderProgram.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "engine/render/BuiltinShaders.h"
#include "engine/render/RenderError.h"
#include "tests/render/support/GlTestContext.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::render {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::string kShaderDir = std::string(HEMIROLL_SOURCE_DIR) + "/assets/shaders";

TEST(ShaderProgramTest, ShippedShadersCompileAndTheBuiltInsAreTheirCopies) {
  test::useGlContext();
  std::string note;
  ShaderProgram p = ShaderProgram::loadWithFallback(kShaderDir, "scene", {kBuiltinSceneVertex, "v"},
                                                    {kBuiltinSceneFragment, "f"}, note);
  EXPECT_TRUE(note.empty()) << note;
  EXPECT_NE(p.id(), 0u);
  EXPECT_GE(p.uniform("uViewProjection"), 0);
  EXPECT_EQ(slurp(kShaderDir + "/scene.vert"), kBuiltinSceneVertex);
  EXPECT_EQ(slurp(kShaderDir + "/scene.frag"), kBuiltinSceneFragment);
}

TEST(ShaderProgramTest, ACompileErrorNamesFileAndLine) {
  test::useGlContext();
  const ShaderSource vertex{kBuiltinSceneVertex, "scene.vert"};
  const ShaderSource broken{"#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0) + undefinedThing; }\n",
                            "broken.frag"};
  try {
    ShaderProgram::compile(vertex, broken);
    FAIL() << "a broken shader compiled";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.frag:3:"), std::string::npos) << e.what();
  }
}

TEST(ShaderProgramTest, MissingOrBrokenFilesFallBackToTheBuiltIns) {
  test::useGlContext();
  test::TempDirectory dir;
  std::string note;
  ShaderProgram missing = ShaderProgram::loadWithFallback(dir.path().string(), "scene", {kBuiltinSceneVertex, "v"},
                                                          {kBuiltinSceneFragment, "f"}, note);
  EXPECT_NE(missing.id(), 0u);
  EXPECT_NE(note.find("scene.vert: cannot read it"), std::string::npos) << note;

  dir.write("scene.vert", kBuiltinSceneVertex);
  dir.write("scene.frag", "#version 330 core\n\nvoid main() { gl_FragColor = 1; }\n");
  ShaderProgram broken = ShaderProgram::loadWithFallback(dir.path().string(), "scene", {kBuiltinSceneVertex, "v"},
                                                         {kBuiltinSceneFragment, "f"}, note);
  EXPECT_NE(broken.id(), 0u);
  EXPECT_NE(note.find("scene.frag:3:"), std::string::npos) << note;
  EXPECT_NE(note.find("built-in"), std::string::npos) << note;
}

TEST(ShaderProgramTest, LogsOfBothDriverFamiliesMapToFileLine) {
  EXPECT_EQ(mapShaderLog("0:12(5): error: `x' undeclared\n", "a.frag"), "a.frag:12: error: `x' undeclared");
  EXPECT_EQ(mapShaderLog("0(7) : error C0000: syntax error\n", "b.vert"), "b.vert:7: error C0000: syntax error");
  EXPECT_EQ(mapShaderLog("something odd", "c.frag"), "c.frag: something odd");
  EXPECT_NE(mapShaderLog("", "d.frag").find("d.frag"), std::string::npos);
}

}  // namespace
}  // namespace hemiroll::render
