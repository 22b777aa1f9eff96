#pragma once
// A device's own frame and length unit against the bridge's: x right, y away
// from the user, z up, metres (docs/UDP_BRIDGE.md). Every SDK names its axes
// differently (OpenHaptics: y up, z towards the user, millimetres; Force
// Dimension: x towards the user, y right, z up, metres); the map is a signed
// permutation and a scale, so it is exact and its inverse is its transpose.

#include <array>
#include <optional>
#include <string>

namespace hemiroll::sdkclients {

using Vec3 = std::array<double, 3>;

struct AxisMap {
  // Bridge axis i is the device's axis source[i] times sign[i].
  std::array<int, 3> source{0, 1, 2};
  std::array<int, 3> sign{1, 1, 1};
  double metresPerUnit = 1.0;  // the SDK's length unit in metres (0.001 for millimetres)
  Vec3 origin{};               // the workspace's centre in the device's frame and unit

  // A position from the device, in the bridge's frame [m], from the centre.
  Vec3 positionToBridge(const Vec3& device) const;
  // A velocity from the device, in the bridge's frame [m/s].
  Vec3 velocityToBridge(const Vec3& device) const;
  // A force from the bridge [N], in the device's frame [N]: forces keep newtons.
  Vec3 forceToDevice(const Vec3& bridge) const;
  // Why the map is not a signed permutation with a positive scale; nullopt when it is.
  std::optional<std::string> problem() const;
};

// The maps of the SDKs the clients in tools/sdkclients use, from their
// makers' documentation (UDP_BRIDGE.md, "Clients for device SDKs").
AxisMap openHapticsAxes();     // x right, y up, z towards the user; mm
AxisMap forceDimensionAxes();  // x towards the user, y right, z up; m
AxisMap libnifalconAxes();     // x right, y up, z towards the user; m; centre 0.11 m out

}  // namespace hemiroll::sdkclients
