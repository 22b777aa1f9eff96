#pragma once
// Device coordinates -> scene (base frame of the physics), and forces back.
// p_scene = scale * p_device + offset; v_scene = scale * v_device.
// Forces go back as F_device = forceGain * scale * F_scene: with forceGain = 1
// the power is the same on both sides (F_d . v_d = F_s . v_s), so the mapping
// adds no energy to the coupled loop, whatever the scale.

#include "engine/haptics/HapticDevice.h"

namespace hemiroll::haptics {

struct WorkspaceMapping {
  double scale = 1.0;            // scene metres per device metre [-]
  Vec3 offset = Vec3::Zero();    // scene position of the device origin [m]
  double forceGain = 1.0;        // extra gain on the rendered force [-]; > 1 injects energy

  Vec3 positionToScene(const Vec3& p) const { return scale * p + offset; }
  Vec3 velocityToScene(const Vec3& v) const { return scale * v; }
  Vec3 forceToDevice(const Vec3& sceneForce) const { return (forceGain * scale) * sceneForce; }
  // The inverse of forceToDevice (what a hand on the device feels, in the scene).
  Vec3 forceToScene(const Vec3& deviceForce) const { return deviceForce / (forceGain * scale); }
};

}  // namespace hemiroll::haptics
