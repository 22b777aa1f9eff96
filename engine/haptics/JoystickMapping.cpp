#include "engine/haptics/JoystickMapping.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::haptics {

double axisToUnit(std::int16_t raw, double deadZone) {
  // -32768 would be just past -1; the range is symmetric at 32767.
  const double v = std::clamp(static_cast<double>(raw) / 32767.0, -1.0, 1.0);
  const double dz = std::clamp(deadZone, 0.0, 0.99);
  const double magnitude = std::abs(v);
  if (magnitude <= dz) return 0.0;
  return std::copysign((magnitude - dz) / (1.0 - dz), v);
}

Vec3 axesToPosition(const JoystickMappingDef& def, const std::int16_t* axes, int axisCount) {
  auto axis = [&](int i) { return i >= 0 && i < axisCount ? axisToUnit(axes[i], def.deadZone) : 0.0; };
  const Vec3 centre(def.centre[0], def.centre[1], def.centre[2]);
  return centre + def.reach * Vec3(axis(def.axisX), -axis(def.axisY), def.axisZ >= 0 ? -axis(def.axisZ) : 0.0);
}

ConstantForceCommand forceToConstantEffect(const Vec3& force, double maxForce) {
  ConstantForceCommand c;
  const double fx = force.x(), fy = force.y();
  const double planar = std::hypot(fx, fy);
  if (!std::isfinite(planar) || planar == 0.0 || !(maxForce > 0.0)) return c;
  const double fraction = std::min(planar / maxForce, 1.0);
  c.level = static_cast<std::int16_t>(std::lround(fraction * 32767.0));
  // Any multiple encodes the same direction; 10^4 keeps three digits of angle.
  c.direction = {static_cast<std::int32_t>(std::lround(-fx / planar * 10000.0)),
                 static_cast<std::int32_t>(std::lround(fy / planar * 10000.0)), 0};
  return c;
}

}  // namespace hemiroll::haptics
