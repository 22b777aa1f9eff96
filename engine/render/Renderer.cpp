#include "engine/render/Renderer.h"

#include <epoxy/gl.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "engine/render/BuiltinShaders.h"
#include "engine/render/HemisphereMesh.h"
#include "engine/render/MeshLoader.h"
#include "engine/render/PrimitiveMeshes.h"
#include "engine/render/SceneGeometry.h"

namespace hemiroll::render {

namespace {

constexpr float kSky[3] = {0.62f, 0.72f, 0.84f};
constexpr Rgba kFloor{0.82f, 0.81f, 0.78f, 1.0f};
constexpr Rgba kMassPoint{0.95f, 0.75f, 0.10f, 1.0f};
constexpr Rgba kProxy{0.20f, 0.45f, 0.95f, 0.85f};
constexpr Rgba kArrow{0.95f, 0.30f, 0.10f, 1.0f};
constexpr Rgba kHint{0.25f, 0.95f, 0.55f, 0.75f};  // the autopilot's hint: green, apart from the proxy's blue
constexpr Rgba kWhite{1, 1, 1, 1};
constexpr Rgba kGhost{0.55f, 0.75f, 1.0f, 0.35f};  // translucent: the live hemisphere shows through
constexpr double kMassPointRadii = 0.12;  // [R]: visible at the follow distance, small beside the face
constexpr double kProxyRadii = 0.10;      // [R]
constexpr double kShadowRadii = 0.9;      // [R]
constexpr float kXrayAlpha = 0.55f;        // floor lines seen through the solids
constexpr std::size_t kXrayTraceVertices = 512;  // the trace's newest 256 segments go through the solids
constexpr std::size_t kSpringVertices = 512;  // appendSpringCoil: 8 turns x 12 segments x 2
constexpr int kRingSegments = 48;
constexpr std::size_t kRingVertices = 6 * kRingSegments;  // appendFlatRing
// Room for the trace plus the target/zone outlines and a spring coil.
constexpr std::size_t kExtraLineVertices = 8192;
constexpr std::size_t kExamplePathVertices = 2048;  // scene.example_path's 2000 points, dashed: 2000 vertices
constexpr std::size_t kDecalVertices = 8192;

Eigen::Vector3f toVec(const Vec3d& v) { return {float(v[0]), float(v[1]), float(v[2])}; }

Eigen::Matrix4f translateScale(const Eigen::Vector3f& t, float s) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.topLeftCorner<3, 3>() *= s;
  m.topRightCorner<3, 1>() = t;
  return m;
}

Eigen::Matrix3f rotationOf(const Mat3d& r) {
  Eigen::Matrix3f m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = float(r[3 * i + j]);
  return m;
}

}  // namespace

Renderer::Renderer(const RendererDef& def) : def_(def) {
  std::string note;
  program_ = ShaderProgram::loadWithFallback(def_.assetsDir + "/shaders", "scene",
                                             {kBuiltinSceneVertex, "built-in scene.vert"},
                                             {kBuiltinSceneFragment, "built-in scene.frag"}, note);
  if (!note.empty()) notes_.push_back(note);
  u_ = {program_.uniform("uModel"), program_.uniform("uViewProjection"), program_.uniform("uNormalMatrix"),
        program_.uniform("uLit"),   program_.uniform("uTint"),           program_.uniform("uLightDirection"),
        program_.uniform("uEye")};

  hemisphere_ = GpuMesh::makeStatic(makeHemisphereMesh());
  sphere_ = GpuMesh::makeStatic(makeSphereMesh());
  arrow_ = GpuMesh::makeStatic(makeArrowMesh());
  shadow_ = GpuMesh::makeStatic(makeDiscMesh(32, {0, 0, 0, 0.45f}, {0, 0, 0, 0}));
  grid_ = GpuMesh::makeStatic(makeFloorGrid(def_.gridExtent, def_.fineGridExtent));
  if (!def_.proxyMesh.empty()) {
    LoadedMesh loaded = loadMeshFile(def_.assetsDir + "/" + def_.proxyMesh, kWhite);
    if (loaded.mesh) proxy_ = GpuMesh::makeStatic(*loaded.mesh);
    else notes_.push_back(loaded.error + " (using the built-in proxy marker)");
  }
  if (!proxy_.valid()) proxy_ = GpuMesh::makeStatic(makeOctahedronMesh(kWhite));

  const std::size_t lineCapacity = 2 * def_.traceCapacity + kExtraLineVertices;
  lines_ = GpuMesh::makeDynamic(Primitive::Lines, lineCapacity);
  decals_ = GpuMesh::makeDynamic(Primitive::Triangles, kDecalVertices);
  spring_ = GpuMesh::makeDynamic(Primitive::Lines, kSpringVertices);
  ring_ = GpuMesh::makeDynamic(Primitive::Triangles, kRingVertices);
  ringScratch_.reserve(kRingVertices);
  lineScratch_.reserve(lineCapacity);
  springScratch_.reserve(kSpringVertices);
  decalScratch_.reserve(kDecalVertices);
  clean_.targets.reserve(16);
  clean_.forbidden.reserve(16);
}

Renderer::~Renderer() = default;

void Renderer::drawMesh(const GpuMesh& mesh, const Eigen::Matrix4f& model, Rgba tint, bool lit) {
  setUniforms(model, tint, lit);
  mesh.draw();
}

void Renderer::setUniforms(const Eigen::Matrix4f& model, Rgba tint, bool lit) {
  glUniformMatrix4fv(u_.model, 1, GL_FALSE, model.data());
  const Eigen::Matrix3f normal = model.topLeftCorner<3, 3>().inverse().transpose();
  glUniformMatrix3fv(u_.normalMatrix, 1, GL_FALSE, normal.data());
  glUniform4f(u_.tint, tint.r, tint.g, tint.b, tint.a);
  glUniform1i(u_.lit, lit ? 1 : 0);
}

void Renderer::render(const RenderScene& scene, int width, int height) {
  lastClean_ = sanitizer_.sanitize(scene, clean_);
  const RenderScene& s = clean_;
  camera_ = makeCameraView(s.camera, s.centre, s.radius, height > 0 ? double(width) / height : 1.0);

  glViewport(0, 0, width, height);
  clearFloorAndSky(width, height);
  program_.use();
  glUniformMatrix4fv(u_.viewProjection, 1, GL_FALSE, camera_.viewProjection.data());
  const Eigen::Vector3f light = Eigen::Vector3f(0.4f, -0.5f, 0.75f).normalized();
  glUniform3f(u_.lightDirection, light.x(), light.y(), light.z());
  glUniform3f(u_.eye, camera_.eye.x(), camera_.eye.y(), camera_.eye.z());
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_CULL_FACE);  // the face disc and the markers are seen from both sides

  drawFloorLayer(s);
  drawSolids(s);
  drawProps();
  if (s.ghost.shown) drawGhost(s);
  // X-ray: the outlines and the trace once more over everything, faint. The
  // hemisphere sits on its own contact point, so millimetre targets and the
  // trace's head would otherwise be hidden exactly where the player looks.
  // Only the trace's recent part: the head is what hides under the body,
  // and each line costs the software rasteriser per pixel.
  glDisable(GL_DEPTH_TEST);
  // The example path lies mostly under the hemisphere (a tutorial's few
  // centimetres): shown through it at full strength, it is the lesson; the
  // outlines after it, faint.
  const std::size_t path = std::min(examplePathVertices_, outlineVertices_);
  setUniforms(Eigen::Matrix4f::Identity(), {1, 1, 1, 1}, false);
  lines_.drawRange(0, path);
  setUniforms(Eigen::Matrix4f::Identity(), {1, 1, 1, kXrayAlpha}, false);
  lines_.drawRange(path, outlineVertices_ - path);
  const std::size_t traceVertices = lines_.count() - outlineVertices_;
  const std::size_t recent = std::min(traceVertices, kXrayTraceVertices);
  lines_.drawRange(lines_.count() - recent, recent);
  // The strain ring last, through everything: it sits at the proxy's
  // height, where the tilted face would hide half of it.
  if (s.showProxy && s.showProxyRing) {
    ringScratch_.clear();
    const std::array<float, 4>& c = s.proxyRingColour;
    const double outer = s.proxyRingRadius, width = std::max(0.04 * s.radius, 0.12 * outer);
    appendFlatRing(s.proxyPosition, std::max(0.0, outer - width), outer, kRingSegments, Rgba{c[0], c[1], c[2], c[3]},
                   ringScratch_);
    ring_.update(ringScratch_.data(), ringScratch_.size());
    drawMesh(ring_, Eigen::Matrix4f::Identity(), kWhite, false);
  }
}

// The floor is the clear colour and the sky a second, scissored clear above
// the plane's horizon: no full-screen polygon, which under a software
// rasteriser costs more than everything else in the frame together. The
// horizon is where the plane's points at infinity land: the image of the
// horizontal viewing direction with w = 0, one row for a camera without roll.
void Renderer::clearFloorAndSky(int width, int height) {
  glDisable(GL_SCISSOR_TEST);
  glClearColor(kFloor.r, kFloor.g, kFloor.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const Eigen::Vector3f forward = -camera_.view.row(2).head<3>().transpose();
  const Eigen::Vector2f horizontal(forward.x(), forward.y());
  if (horizontal.norm() < 1e-4f) return;  // looking straight down: no horizon in view
  const Eigen::Vector2f h = horizontal.normalized();
  const Eigen::Vector4f clip = camera_.viewProjection * Eigen::Vector4f(h.x(), h.y(), 0.0f, 0.0f);
  if (clip.w() <= 0.0f) return;
  const float ndcY = clip.y() / clip.w();
  const int skyStart = std::clamp(int(std::ceil((ndcY + 1.0f) * 0.5f * float(height))), 0, height);
  if (skyStart >= height) return;
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, skyStart, width, height - skyStart);
  glClearColor(kSky[0], kSky[1], kSky[2], 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

void Renderer::drawFloorLayer(const RenderScene& s) {
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  const Eigen::Matrix4f identity = Eigen::Matrix4f::Identity();
  // The grid moves with the focus in whole decimetres, so its lines stay on
  // world centimetres while only the part near the hemisphere is drawn.
  const Eigen::Vector3f gridOrigin(float(std::round(s.centre[0] * 10.0) / 10.0),
                                   float(std::round(s.centre[1] * 10.0) / 10.0), 0.0f);
  drawMesh(grid_, translateScale(gridOrigin, 1.0f), kWhite, false);

  decalScratch_.clear();
  appendZoneFills(s, decalScratch_);
  appendTargetFills(s, def_.floorExtent, decalScratch_);
  decals_.update(decalScratch_.data(), decalScratch_.size());
  drawMesh(decals_, identity, kWhite, false);

  // The contact shadow: under the contact point, which is below the sphere centre.
  const Eigen::Vector3f contact(float(s.centre[0]), float(s.centre[1]), 0.0f);
  drawMesh(shadow_, translateScale(contact, float(kShadowRadii * s.radius)), kWhite, false);

  lineScratch_.clear();
  // The example path first: with the outlines, so it shows through the
  // hemisphere (x-ray) where the player's contact point runs along it.
  appendExamplePath(s, kExamplePathVertices, lineScratch_);
  examplePathVertices_ = lineScratch_.size();
  appendZoneOutlines(s, lineScratch_);
  appendTargetOutlines(s, def_.floorExtent, lineScratch_);
  appendTargetPointers(s, lineScratch_);  // with the outlines: drawn over the hemisphere too (x-ray)
  outlineVertices_ = std::min(lineScratch_.size(), lines_.capacity());
  if (s.trace) appendTraceLines(*s.trace, s.time, lineScratch_);
  lines_.update(lineScratch_.data(), lineScratch_.size());
  drawMesh(lines_, identity, kWhite, false);
}

void Renderer::drawSolids(const RenderScene& s) {
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  const float radius = float(s.radius);
  const Eigen::Vector3f centre = toVec(s.centre);
  const Eigen::Matrix3f rotation = rotationOf(s.orientation);

  Eigen::Matrix4f body = Eigen::Matrix4f::Identity();
  body.topLeftCorner<3, 3>() = rotation * radius;
  body.topRightCorner<3, 1>() = centre;
  drawMesh(hemisphere_, body, kWhite, true);

  // The mass point sits on the face: its centre one ball radius above the face plane.
  const float ball = float(kMassPointRadii) * radius;
  const Eigen::Vector3f massPoint =
      centre + rotation * Eigen::Vector3f(float(s.massPoint[0]), float(s.massPoint[1]), ball);
  drawMesh(sphere_, translateScale(massPoint, ball), kMassPoint, true);

  const double forceNorm = std::sqrt(s.force[0] * s.force[0] + s.force[1] * s.force[1] + s.force[2] * s.force[2]);
  const double length = std::min(forceNorm * std::abs(s.forceScale), def_.maxArrowRadii * s.radius);
  if (length > 1e-3 * s.radius) {
    // Rotate +z onto the force direction; thickness follows R, length the force.
    const Eigen::Vector3f dir = Eigen::Vector3f(float(s.force[0]), float(s.force[1]), float(s.force[2])).normalized();
    const Eigen::Matrix3f align = Eigen::Quaternionf::FromTwoVectors(Eigen::Vector3f::UnitZ(), dir).toRotationMatrix();
    Eigen::Matrix4f model = Eigen::Matrix4f::Identity();
    model.topLeftCorner<3, 3>() = align * Eigen::Vector3f(radius, radius, float(length)).asDiagonal();
    model.topRightCorner<3, 1>() = massPoint;
    drawMesh(arrow_, model, kArrow, true);
  }

  if (s.showHint) {
    const Eigen::Vector3f from = toVec(s.hintFrom), to = toVec(s.hintTo);
    drawMesh(proxy_, translateScale(to, 1.6f * float(kProxyRadii) * radius), kHint, true);
    const Eigen::Vector3f way = to - from;
    if (way.norm() > 0.05f * radius) {  // the arrow's mesh spans z in [0, 1]: scaled to the way
      const Eigen::Matrix3f align =
          Eigen::Quaternionf::FromTwoVectors(Eigen::Vector3f::UnitZ(), way.normalized()).toRotationMatrix();
      Eigen::Matrix4f model = Eigen::Matrix4f::Identity();
      model.topLeftCorner<3, 3>() = align * Eigen::Vector3f(radius, radius, way.norm()).asDiagonal();
      model.topRightCorner<3, 1>() = from;
      drawMesh(arrow_, model, kHint, true);
    }
  }

  if (s.showProxy) {
    const Eigen::Vector3f proxy = toVec(s.proxyPosition);
    drawMesh(proxy_, translateScale(proxy, float(kProxyRadii) * radius), kProxy, true);
    if (s.springOn) {
      springScratch_.clear();
      const Vec3d from{massPoint.x(), massPoint.y(), massPoint.z()};
      appendSpringCoil(from, s.proxyPosition, 0.05 * s.radius, 8, springScratch_);
      spring_.update(springScratch_.data(), springScratch_.size());
      drawMesh(spring_, Eigen::Matrix4f::Identity(), kWhite, false);
    }
  }
}

std::vector<std::string> Renderer::setProps(const std::vector<PropDef>& props) {
  std::vector<std::string> notes;
  propMeshes_.clear();
  propBase_.clear();
  props_.clear();
  std::vector<std::string> files;  // propMeshes_[i] was loaded from files[i]
  for (const PropDef& p : props) {
    const bool placed = std::isfinite(p.position[0]) && std::isfinite(p.position[1]) && std::isfinite(p.position[2]) &&
                        std::isfinite(p.size) && p.size > 0.0 && std::isfinite(p.yaw);
    if (!placed) {
      notes.push_back("prop " + p.mesh + ": a non-finite place or a size <= 0; left out");
      continue;
    }
    std::size_t index = std::find(files.begin(), files.end(), p.mesh) - files.begin();
    if (index == files.size()) {
      // White vertices where the file has no colours: the prop's colour tints them.
      LoadedMesh loaded = loadMeshFile(def_.assetsDir + "/" + p.mesh, kWhite);
      if (!loaded.mesh) notes.push_back(loaded.error + " (drawn as the built-in marker)");
      const MeshData mesh = loaded.mesh ? std::move(*loaded.mesh) : makeOctahedronMesh(kWhite);
      float base = 0.0f;
      for (const Vertex& v : mesh.vertices) base = std::min(base, v.position[2]);
      propMeshes_.push_back(GpuMesh::makeStatic(mesh));
      propBase_.push_back(base);
      files.push_back(p.mesh);
    }
    Eigen::Matrix4f model = Eigen::Matrix4f::Identity();
    model.topLeftCorner<3, 3>() =
        Eigen::AngleAxisf(float(p.yaw), Eigen::Vector3f::UnitZ()).toRotationMatrix() * float(p.size);
    // Standing on its position: the bounding box's bottom there, not its centre.
    model.topRightCorner<3, 1>() = toVec(p.position) - Eigen::Vector3f(0.0f, 0.0f, propBase_[index] * float(p.size));
    props_.push_back({index, model, p.colour});
  }
  return notes;
}

void Renderer::drawProps() {
  for (const PlacedProp& p : props_) drawMesh(propMeshes_[p.mesh], p.model, p.tint, true);
}

// After the solids, depth-tested but not written: the ghost is hidden behind
// the live hemisphere where it is behind it, and never hides it. Pushed back
// a few depth steps: where it coincides with the live hemisphere (every
// replayed attempt starts in the same pose) the equal depths would otherwise
// pass and fail the test pixel by pixel, a speckle.
void Renderer::drawGhost(const RenderScene& s) {
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 8.0f);
  const float radius = float(s.radius);
  const Eigen::Vector3f centre = toVec(s.ghost.centre);
  const Eigen::Matrix3f rotation = rotationOf(s.ghost.orientation);
  Eigen::Matrix4f body = Eigen::Matrix4f::Identity();
  body.topLeftCorner<3, 3>() = rotation * radius;
  body.topRightCorner<3, 1>() = centre;
  drawMesh(hemisphere_, body, kGhost, true);
  const float ball = float(kMassPointRadii) * radius;
  const Eigen::Vector3f massPoint =
      centre + rotation * Eigen::Vector3f(float(s.ghost.massPoint[0]), float(s.ghost.massPoint[1]), ball);
  drawMesh(sphere_, translateScale(massPoint, ball), kGhost, true);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthMask(GL_TRUE);
}

}  // namespace hemiroll::render
