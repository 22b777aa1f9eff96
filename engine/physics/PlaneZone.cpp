#include "engine/physics/PlaneZone.h"

namespace hemiroll::physics {

double PlaneZone::clearance(const Vec2& point) const {
  if (circle) return (point - Vec2(centre[0], centre[1])).norm() - radius;
  const Vec2 outside = (Vec2(min[0], min[1]) - point).cwiseMax(point - Vec2(max[0], max[1]));
  if (outside.maxCoeff() <= 0.0) return outside.maxCoeff();
  return outside.cwiseMax(0.0).norm();
}

}  // namespace hemiroll::physics
