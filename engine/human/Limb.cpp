#include "engine/human/Limb.h"

namespace hemiroll::human {

using physics::Vec3;

void Limb::reset(const Vec3& at) {
  position_ = at;
  velocity_ = Vec3::Zero();
}

void Limb::step(const Vec3& intent, const Vec3& intentVelocity, const Vec3& deviceForce, double dt) {
  const Vec3 muscle = def_.stiffness * (intent - position_) + def_.damping * (intentVelocity - velocity_);
  velocity_ += dt * (muscle + deviceForce) / def_.mass;
  position_ += dt * velocity_;
}

}  // namespace hemiroll::human
