#pragma once
// The hand and arm: a point mass pulled towards the intent by the muscles'
// spring and damper, and pushed by what the device renders on it.
//
//   m a = k (intent - x) + b (intent velocity - v) + F_device
//
// Semi-implicit Euler at the servo tick. On a haptic device F_device is the
// coupling force the device renders: it acts at once, through mechanics,
// with no neural delay. A mouse renders nothing (F_device = 0).

#include "engine/human/HumanDef.h"
#include "engine/physics/StateLayout.h"

namespace hemiroll::human {

class Limb {
 public:
  explicit Limb(const LimbDef& def = {}) : def_(def) {}

  void reset(const physics::Vec3& at);
  void step(const physics::Vec3& intent, const physics::Vec3& intentVelocity, const physics::Vec3& deviceForce,
            double dt);

  const physics::Vec3& position() const { return position_; }
  const physics::Vec3& velocity() const { return velocity_; }

 private:
  LimbDef def_;
  physics::Vec3 position_ = physics::Vec3::Zero();
  physics::Vec3 velocity_ = physics::Vec3::Zero();
};

}  // namespace hemiroll::human
