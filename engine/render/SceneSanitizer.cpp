#include "engine/render/SceneSanitizer.h"

#include <cmath>

namespace hemiroll::render {

namespace {

template <std::size_t N>
bool finite(const std::array<double, N>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

// Columns of a row-major 3x3 orthonormal within `tol` (a rotation's columns
// are unit and perpendicular; numerical drift from the physics is ~1e-15).
bool isRotation(const Mat3d& m, double tol = 1e-3) {
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      double dot = 0.0;
      for (int k = 0; k < 3; ++k) dot += m[3 * k + i] * m[3 * k + j];
      if (std::abs(dot - (i == j ? 1.0 : 0.0)) > tol) return false;
    }
  return true;
}

bool goodPose(const RenderScene& s) {
  return finite(s.centre) && finite(s.orientation) && isRotation(s.orientation) && finite(s.massPoint) &&
         std::isfinite(s.radius) && s.radius > 0.0;
}

}  // namespace

bool SceneSanitizer::sanitize(const RenderScene& in, RenderScene& out) {
  bool clean = true;
  out.camera = in.camera;
  if (!(std::isfinite(in.camera.zoom) && in.camera.zoom > 0.0)) out.camera.zoom = 1.0, clean = false;
  if (!std::isfinite(in.camera.yaw)) out.camera.yaw = CameraDef{}.yaw, clean = false;
  if (!std::isfinite(in.camera.pitch)) out.camera.pitch = CameraDef{}.pitch, clean = false;
  if (!(std::isfinite(in.camera.fovY) && in.camera.fovY > 0.05 && in.camera.fovY < 3.0))
    out.camera.fovY = CameraDef{}.fovY, clean = false;

  const RenderScene* pose = &in;
  if (goodPose(in)) {
    lastGood_.radius = in.radius;
    lastGood_.centre = in.centre;
    lastGood_.orientation = in.orientation;
    lastGood_.massPoint = in.massPoint;
    hasGoodPose_ = true;
  } else {
    clean = false;
    pose = &lastGood_;  // the defaults (upright at the origin) until a good pose has been seen
  }
  out.radius = pose->radius;
  out.centre = pose->centre;
  out.orientation = pose->orientation;
  out.massPoint = pose->massPoint;

  out.showProxy = in.showProxy && finite(in.proxyPosition);
  out.proxyPosition = out.showProxy ? in.proxyPosition : Vec3d{};
  out.springOn = in.springOn && out.showProxy;
  bool ringColourOk = true;
  for (float c : in.proxyRingColour) ringColourOk = ringColourOk && std::isfinite(c);
  out.showProxyRing = in.showProxyRing && out.showProxy && std::isfinite(in.proxyRingRadius) &&
                      in.proxyRingRadius > 0.0 && ringColourOk;
  out.proxyRingRadius = out.showProxyRing ? in.proxyRingRadius : 0.0;
  out.proxyRingColour = out.showProxyRing ? in.proxyRingColour : std::array<float, 4>{};
  if (in.showProxyRing && !out.showProxyRing && out.showProxy) clean = false;
  const bool forceOk = finite(in.force) && std::isfinite(in.forceScale);
  out.force = forceOk ? in.force : Vec3d{};
  out.forceScale = forceOk ? in.forceScale : 0.0;
  if ((in.showProxy && !out.showProxy) || !forceOk) clean = false;

  out.showHint = in.showHint && finite(in.hintFrom) && finite(in.hintTo);
  out.hintFrom = out.showHint ? in.hintFrom : Vec3d{};
  out.hintTo = out.showHint ? in.hintTo : Vec3d{};

  // A ghost with a bad pose is left out (the live hemisphere matters more).
  out.ghost = in.ghost;
  if (in.ghost.shown && !(finite(in.ghost.centre) && finite(in.ghost.orientation) &&
                          isRotation(in.ghost.orientation) && finite(in.ghost.massPoint))) {
    out.ghost.shown = false;
    clean = false;
  }

  out.targets.clear();
  for (const TargetMarker& t : in.targets) {
    if (finite(t.position) && finite(t.halfWidth) && t.halfWidth[0] > 0.0 && t.halfWidth[1] > 0.0)
      out.targets.push_back(t);
    else
      clean = false;
  }
  out.forbidden.clear();
  for (const ZoneMarker& z : in.forbidden) {
    const bool ok = z.circle ? finite(z.centre) && std::isfinite(z.radius) && z.radius > 0.0
                             : finite(z.min) && finite(z.max) && z.min[0] < z.max[0] && z.min[1] < z.max[1];
    if (ok) out.forbidden.push_back(z);
    else clean = false;
  }
  out.trace = in.trace;  // ContactTrace refuses non-finite points itself
  out.examplePath.clear();
  for (const Vec2d& p : in.examplePath) {
    if (finite(p)) out.examplePath.push_back(p);
    else clean = false;
  }
  out.time = std::isfinite(in.time) ? in.time : out.time;
  return clean;
}

}  // namespace hemiroll::render
