#pragma once
// Mouse motion [px] -> device coordinates [m] for MouseDevice: the pointer
// steers the proxy on a horizontal plane by its motion, the wheel sets its
// height.
//   (x, y) += Rz(screenYaw) (dx, -dy) * metresPerPixel   (screen right and up)
//   z = height, changed by wheelStep per notch              (up = +z)
//
// Why motion and not the pointer's place in the window: every camera follows
// the rolling hemisphere, so a fixed window-to-plane map would leave the
// proxy ever further from where the player's pointer is (off the window after
// a 15 cm roll), and a map through the moving camera would move the proxy
// whenever the camera moves, a loop that pushes the hemisphere on by itself.
// Moved by motion, the proxy stays where the player left it, the game draws
// it in place of the system cursor, and "right on the screen" is right for
// any camera yaw. The position is kept within reach of the origin and the
// height within [minHeight, maxHeight], so the proxy never leaves the
// workspace.

#include "engine/haptics/HapticDevice.h"

namespace hemiroll::haptics {

struct PointerMappingDef {
  double metresPerPixel = 0.00025;        // 0.25 mm/px: 800 px span 0.2 m, a desk device's workspace
  double wheelStep = 0.002;               // [m] per wheel notch
  double minHeight = -0.05, maxHeight = 0.05;  // [m]
  double reach = 0.1;                     // largest horizontal distance from the origin [m]
};

class PointerMapping {
 public:
  // Throws std::invalid_argument naming the field for a non-positive scale,
  // step or reach, or an empty height range. Starts at the origin.
  explicit PointerMapping(const PointerMappingDef& def = {});

  // The pointer moved by (dx, dy) window pixels (y grows down the screen).
  // Non-finite motion is ignored.
  void moveBy(double dxPx, double dyPx);
  // The heading of screen right in device coordinates [rad] (0: +x; the
  // camera's, see render::screenRightHeading).
  void setScreenYaw(double radians);
  // Wheel notches (positive: away from the user = up); height is clamped.
  void wheel(double notches);
  // Back to a horizontal position [m] (clamped to reach), e.g. the start.
  void moveTo(double x, double y);
  // To a height [m] (clamped), e.g. the mass point's when taking hold.
  void setHeight(double z);

  Vec3 position() const { return Vec3(x_, y_, height_); }
  double height() const { return height_; }
  const PointerMappingDef& def() const { return def_; }

 private:
  void clampToReach();

  PointerMappingDef def_;
  double x_ = 0.0, y_ = 0.0, height_ = 0.0;
  double cosYaw_ = 1.0, sinYaw_ = 0.0;
};

}  // namespace hemiroll::haptics
