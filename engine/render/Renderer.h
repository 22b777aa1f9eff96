#pragma once
// Draws a RenderScene with OpenGL 3.3 core into the bound framebuffer (the
// window's, or an offscreen Framebuffer). No game rules: it draws what the
// scene says. Construct it with a current GL context (platform::Window);
// keep it for the life of the context.
//
// One frame, in order: floor and sky (two clears), 1 cm / 10 cm grid,
// forbidden zones, target bands, contact shadow, trace (no depth test: all
// lie on the plane); then with depth test the hemisphere, the mass point, the
// proxy, the force arrow and the spring, the level's props; a ghost (translucent, depth-tested,
// not written), when the scene has one; last, the outlines and the trace's
// newest part once more over everything, faint (targets under the hemisphere
// stay visible). Scratch vertex buffers and dynamic GPU buffers are sized at
// construction: after the first frame, render() allocates nothing.

#include <memory>
#include <string>
#include <vector>

#include "engine/render/Camera.h"
#include "engine/render/GpuMesh.h"
#include "engine/render/RenderScene.h"
#include "engine/render/SceneSanitizer.h"
#include "engine/render/ShaderProgram.h"

namespace hemiroll::render {

struct RendererDef {
  std::string assetsDir = "assets";        // holds shaders/ and meshes/; missing files -> built-ins
  std::string proxyMesh = "meshes/proxy.obj";  // relative to assetsDir; "" = the built-in octahedron
  std::size_t traceCapacity = 4096;        // the most trace points drawn (ContactTraceDef.capacity)
  double floorExtent = 0.5;                // target bands of free components end here [m]
  double gridExtent = 0.5;                 // 10 cm lines within this of the focus [m]
  double fineGridExtent = 0.2;             // 1 cm lines within this of the focus [m]
  double maxArrowRadii = 6.0;              // the force arrow is at most this many R long
};

// Scenery a level names: a mesh file placed on the plane. Static for the
// level: setProps() loads the meshes once, render() only draws them.
struct PropDef {
  std::string mesh;                        // relative to the assets directory (glTF, GLB, OBJ)
  Vec3d position{};                        // base frame: where it stands, the middle of its bounding box's bottom [m]
  double size = 0.01;                      // radius of the sphere the mesh is scaled to [m]
  double yaw = 0.0;                        // turn about the vertical [rad]
  Rgba colour{1.0f, 1.0f, 1.0f, 1.0f};     // multiplies the mesh's colours (white where the file has none)
};

class Renderer {
 public:
  explicit Renderer(const RendererDef& def = {});  // throws RenderError (no usable shaders)
  ~Renderer();

  // Draws into the currently bound framebuffer of this size [GL px].
  void render(const RenderScene& scene, int width, int height);

  // Replaces the props drawn with every frame (a level's scenery; {} = none).
  // Each file loads once; a mesh that cannot be loaded is drawn as the
  // built-in marker, and a prop with a non-finite place or a size <= 0 is
  // left out: both named in the returned sentences. Outside render().
  std::vector<std::string> setProps(const std::vector<PropDef>& props);

  // Fallbacks taken while loading (missing or broken shader/mesh files), as
  // sentences naming the file; empty when every asset loaded.
  const std::vector<std::string>& notes() const { return notes_; }
  // The camera of the last frame (tests project world points with it).
  const CameraView& camera() const { return camera_; }
  // False when the last scene had non-finite or invalid parts (replaced or skipped).
  bool lastSceneClean() const { return lastClean_; }

 private:
  void drawMesh(const GpuMesh& mesh, const Eigen::Matrix4f& model, Rgba tint, bool lit);
  void setUniforms(const Eigen::Matrix4f& model, Rgba tint, bool lit);
  void clearFloorAndSky(int width, int height);
  void drawFloorLayer(const RenderScene& s);
  void drawSolids(const RenderScene& s);
  void drawGhost(const RenderScene& s);
  void drawProps();

  RendererDef def_;
  std::vector<std::string> notes_;
  ShaderProgram program_;
  struct Uniforms {
    int model, viewProjection, normalMatrix, lit, tint, lightDirection, eye;
  } u_{};
  GpuMesh hemisphere_, sphere_, arrow_, shadow_, grid_, proxy_;
  GpuMesh decals_, lines_, spring_, ring_;    // dynamic
  std::vector<Vertex> decalScratch_, lineScratch_, springScratch_, ringScratch_;
  std::size_t outlineVertices_ = 0;    // lines_ holds the outlines first (the example path first of all), then the trace
  std::size_t examplePathVertices_ = 0;
  struct PlacedProp {
    std::size_t mesh;                  // index into propMeshes_
    Eigen::Matrix4f model;
    Rgba tint;
  };
  std::vector<GpuMesh> propMeshes_;
  std::vector<float> propBase_;        // lowest z of each prop mesh (unit sphere scale)
  std::vector<PlacedProp> props_;
  SceneSanitizer sanitizer_;
  RenderScene clean_;
  CameraView camera_;
  bool lastClean_ = true;
};

}  // namespace hemiroll::render
