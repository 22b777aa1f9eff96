#pragma once
// Mouse pointer [px] -> device coordinates [m] for MouseDevice: the pointer
// moves the proxy on a horizontal plane, the wheel sets its height.
//   x = (px - centreX) * metresPerPixel          (screen right = +x)
//   y = (centreY - py) * metresPerPixel          (screen up = +y; pixel rows grow downwards)
//   z = height, changed by wheelStep per notch   (up = +z)
// The horizontal position is kept within reach of the origin and the height
// within [minHeight, maxHeight], so the proxy never leaves the workspace.

#include "engine/haptics/HapticDevice.h"

namespace hemiroll::haptics {

struct PointerMappingDef {
  double metresPerPixel = 0.00025;        // 0.25 mm/px: 800 px span 0.2 m, a desk device's workspace
  double centreX = 400.0, centreY = 300.0;  // the pixel that maps to the origin [px] (window centre)
  double wheelStep = 0.002;               // [m] per wheel notch
  double minHeight = -0.05, maxHeight = 0.05;  // [m]
  double reach = 0.1;                     // largest horizontal distance from the origin [m]
};

class PointerMapping {
 public:
  // Throws std::invalid_argument naming the field for a non-positive scale,
  // step or reach, or an empty height range.
  explicit PointerMapping(const PointerMappingDef& def = {});

  Vec3 toMetres(double px, double py) const;
  // Wheel notches (positive: away from the user = up); height is clamped.
  void wheel(double notches);
  // The window was resized: its new centre [px].
  void setCentre(double px, double py);
  double height() const { return height_; }
  const PointerMappingDef& def() const { return def_; }

 private:
  PointerMappingDef def_;
  double height_ = 0.0;
};

}  // namespace hemiroll::haptics
