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
  if (!std::isfinite(def.centreX) || !std::isfinite(def.centreY))
    throw std::invalid_argument("PointerMapping: the centre must be finite");
  height_ = std::clamp(0.0, def.minHeight, def.maxHeight);
}

Vec3 PointerMapping::toMetres(double px, double py) const {
  double x = (px - def_.centreX) * def_.metresPerPixel;
  double y = (def_.centreY - py) * def_.metresPerPixel;
  if (!std::isfinite(x) || !std::isfinite(y)) x = y = 0.0;
  const double r = std::hypot(x, y);
  if (r > def_.reach) {
    x *= def_.reach / r;
    y *= def_.reach / r;
  }
  return Vec3(x, y, height_);
}

void PointerMapping::wheel(double notches) {
  if (!std::isfinite(notches)) return;
  height_ = std::clamp(height_ + notches * def_.wheelStep, def_.minHeight, def_.maxHeight);
}

void PointerMapping::setCentre(double px, double py) {
  if (!std::isfinite(px) || !std::isfinite(py)) return;
  def_.centreX = px;
  def_.centreY = py;
}

}  // namespace hemiroll::haptics
