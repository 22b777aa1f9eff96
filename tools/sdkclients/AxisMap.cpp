#include "tools/sdkclients/AxisMap.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::sdkclients {

Vec3 AxisMap::positionToBridge(const Vec3& device) const {
  return velocityToBridge({device[0] - origin[0], device[1] - origin[1], device[2] - origin[2]});
}

Vec3 AxisMap::velocityToBridge(const Vec3& device) const {
  Vec3 out{};
  for (int i = 0; i < 3; ++i) out[i] = sign[i] * device[source[i]] * metresPerUnit;
  return out;
}

Vec3 AxisMap::forceToDevice(const Vec3& bridge) const {
  Vec3 out{};
  for (int i = 0; i < 3; ++i) out[source[i]] = sign[i] * bridge[i];
  return out;
}

std::optional<std::string> AxisMap::problem() const {
  std::array<int, 3> seen{};
  for (int i = 0; i < 3; ++i) {
    if (source[i] < 0 || source[i] > 2) return "an axis map names device axis " + std::to_string(source[i]) + " (0, 1 or 2)";
    if (sign[i] != 1 && sign[i] != -1) return "an axis map's signs are +1 or -1";
    ++seen[source[i]];
  }
  if (std::any_of(seen.begin(), seen.end(), [](int n) { return n != 1; }))
    return "an axis map takes each device axis exactly once";
  if (!(metresPerUnit > 0.0) || !std::isfinite(metresPerUnit)) return "an axis map's unit is a positive length in metres";
  return std::nullopt;
}

// OpenHaptics (HD API reference, HD_CURRENT_POSITION): millimetres; x to the
// user's right, y up, z towards the user. Bridge y (away) is -z, z (up) is y.
AxisMap openHapticsAxes() { return AxisMap{{0, 2, 1}, {1, -1, 1}, 1e-3, {}}; }

// Force Dimension (DHD SDK, dhdGetPosition): metres; x towards the user, y to
// the right, z up. Bridge x (right) is y, y (away) is -x.
AxisMap forceDimensionAxes() { return AxisMap{{1, 0, 2}, {1, -1, 1}, 1.0, {}}; }

// libnifalcon (FalconKinematicStamper::getPosition): metres; x right, y up,
// z towards the user, the origin behind the grip: the workspace's centre is
// about 0.11 m out along z (libnifalcon's examples). Not checked on a Falcon
// here: UDP_BRIDGE.md's acceptance steps start with the axes for that reason.
AxisMap libnifalconAxes() { return AxisMap{{0, 2, 1}, {1, -1, 1}, 1.0, {0.0, 0.0, 0.11}}; }

}  // namespace hemiroll::sdkclients
