#pragma once
// The camera: view and projection matrices from a CameraDef, the point it
// looks at and the drawable's aspect ratio. Pure math (no GL), so projection
// is tested without a window, and render tests can ask where a world point
// lands in pixels.
//
// Modes (RenderScene.h): Follow looks from the -y side, so screen right is
// +x and screen "away" is +y, as the mouse's PointerMapping moves the proxy;
// Orbit turns the eye by yaw/pitch around the focus; Top looks straight down
// with +y up the screen. Distances scale with the hemisphere's radius, so a
// 4 cm and a 40 cm hemisphere fill the screen alike; zoom divides them.

#include <Eigen/Core>

#include "engine/render/RenderScene.h"

namespace hemiroll::render {

struct CameraView {
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f projection = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f viewProjection = Eigen::Matrix4f::Identity();
  Eigen::Vector3f eye = Eigen::Vector3f::Zero();
};

struct PixelPoint {
  double x = 0.0, y = 0.0;  // pixels, origin top-left, y down (as an image)
  bool visible = false;     // in front of the eye and inside the viewport
};

// Eye distance from the focus in radii at zoom 1.
inline constexpr double kFollowDistanceRadii = 7.0;
inline constexpr double kTopDistanceRadii = 10.0;
inline constexpr double kFollowPitch = 0.6;  // [rad] above the plane

// `focus` is what the camera looks at (the sphere centre, base frame [m]);
// `aspect` = drawable width / height (> 0).
CameraView makeCameraView(const CameraDef& def, const Vec3d& focus, double radius, double aspect);

// The heading of screen right on the plane [rad, from +x about +z]: 0 for the
// follow and top cameras, the eye's yaw + pi/2 for orbit. The mouse turns its
// strokes by it (haptics::PointerMapping::setScreenYaw), so that a stroke to
// the right moves the proxy to the right on screen.
double screenRightHeading(const CameraDef& def);

// Where a base-frame point [m] lands in a width x height image.
PixelPoint projectToPixel(const CameraView& view, const Vec3d& point, int width, int height);

Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target, const Eigen::Vector3f& up);
Eigen::Matrix4f perspective(float fovY, float aspect, float zNear, float zFar);

}  // namespace hemiroll::render
