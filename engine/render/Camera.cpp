#include "engine/render/Camera.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace hemiroll::render {

Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target, const Eigen::Vector3f& up) {
  const Eigen::Vector3f f = (target - eye).normalized();
  const Eigen::Vector3f s = f.cross(up).normalized();
  const Eigen::Vector3f u = s.cross(f);
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.row(0).head<3>() = s;
  m.row(1).head<3>() = u;
  m.row(2).head<3>() = -f;
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4f perspective(float fovY, float aspect, float zNear, float zFar) {
  const float t = 1.0f / std::tan(fovY / 2.0f);
  Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = (zFar + zNear) / (zNear - zFar);
  m(2, 3) = 2.0f * zFar * zNear / (zNear - zFar);
  m(3, 2) = -1.0f;
  return m;
}

CameraView makeCameraView(const CameraDef& def, const Vec3d& focusIn, double radius, double aspect) {
  const Eigen::Vector3f focus{float(focusIn[0]), float(focusIn[1]), float(focusIn[2])};
  const double zoom = def.zoom > 0.0 ? def.zoom : 1.0;
  double yaw = -M_PI / 2.0, pitch = kFollowPitch, distance = kFollowDistanceRadii * radius / zoom;
  Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
  switch (def.mode) {
    case CameraMode::Follow:
      break;
    case CameraMode::Orbit:
      yaw = def.yaw;
      pitch = std::clamp(def.pitch, 0.05, 1.5);  // never under the floor nor exactly overhead
      break;
    case CameraMode::Top:
      pitch = M_PI / 2.0;
      distance = kTopDistanceRadii * radius / zoom;
      up = Eigen::Vector3f::UnitY();  // z up is degenerate looking straight down
      break;
  }
  const Eigen::Vector3f offset(float(std::cos(pitch) * std::cos(yaw)), float(std::cos(pitch) * std::sin(yaw)),
                               float(std::sin(pitch)));
  CameraView v;
  v.eye = focus + float(distance) * offset;
  v.view = lookAt(v.eye, focus, up);
  // Near/far as fractions of the distance: the depth buffer's precision
  // follows the scene's scale.
  v.projection = perspective(float(def.fovY), float(aspect > 0.0 ? aspect : 1.0), float(distance * 0.02),
                             float(distance * 50.0));
  v.viewProjection = v.projection * v.view;
  return v;
}

double screenRightHeading(const CameraDef& def) {
  return def.mode == CameraMode::Orbit ? def.yaw + M_PI / 2.0 : 0.0;
}

PixelPoint projectToPixel(const CameraView& view, const Vec3d& p, int width, int height) {
  const Eigen::Vector4f clip = view.viewProjection * Eigen::Vector4f(float(p[0]), float(p[1]), float(p[2]), 1.0f);
  PixelPoint out;
  if (clip.w() <= 0.0f) return out;
  const double nx = clip.x() / clip.w(), ny = clip.y() / clip.w();
  out.x = (nx + 1.0) * 0.5 * width;
  out.y = (1.0 - ny) * 0.5 * height;
  out.visible = std::abs(nx) <= 1.0 && std::abs(ny) <= 1.0;
  return out;
}

}  // namespace hemiroll::render
