#include "engine/haptics/PointerMapping.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hemiroll::haptics {

PointerMapping::PointerMapping(const PointerMappingDef& def) : def_(def) {
  auto positive = [](double x) { return x > 0.0 && std::isfinite(x); };
  if (!positive(def.metresPerPixel)) throw std::invalid_argument("PointerMapping: metresPerPixel must be positive");
  if (!positive(def.wheelStep)) throw std::invalid_argument("PointerMapping: wheelStep must be positive");
  if (!positive(def.reach)) throw std::invalid_argument("PointerMapping: reach must be positive");
  if (!(def.minHeight <= def.maxHeight) || !std::isfinite(def.minHeight) || !std::isfinite(def.maxHeight))
    throw std::invalid_argument("PointerMapping: minHeight must not exceed maxHeight");
  height_ = std::clamp(0.0, def.minHeight, def.maxHeight);
}

void PointerMapping::moveBy(double dxPx, double dyPx) {
  const double right = dxPx * def_.metresPerPixel, up = -dyPx * def_.metresPerPixel;
  if (!std::isfinite(right) || !std::isfinite(up)) return;
  x_ += cosYaw_ * right - sinYaw_ * up;
  y_ += sinYaw_ * right + cosYaw_ * up;
  clampToReach();
}

void PointerMapping::setScreenYaw(double radians) {
  if (!std::isfinite(radians)) return;
  cosYaw_ = std::cos(radians);
  sinYaw_ = std::sin(radians);
}

void PointerMapping::wheel(double notches) {
  if (!std::isfinite(notches)) return;
  height_ = std::clamp(height_ + notches * def_.wheelStep, def_.minHeight, def_.maxHeight);
}

void PointerMapping::moveTo(double x, double y) {
  if (!std::isfinite(x) || !std::isfinite(y)) return;
  x_ = x;
  y_ = y;
  clampToReach();
}

void PointerMapping::setHeight(double z) {
  if (!std::isfinite(z)) return;
  height_ = std::clamp(z, def_.minHeight, def_.maxHeight);
}

void PointerMapping::clampToReach() {
  const double r = std::hypot(x_, y_);
  if (r > def_.reach) {
    x_ *= def_.reach / r;
    y_ *= def_.reach / r;
  }
}

}  // namespace hemiroll::haptics
