#include "engine/physics/ForceInput.h"

#include <cstring>

namespace hemiroll::physics {

void ForceInput::setFree() {
  ++revision_;
  mode_ = Mode::Free;
  proxyFn_ = nullptr;
}

void ForceInput::setFaceForce(const Vec2& f) {
  ++revision_;
  mode_ = Mode::FaceForce;
  faceForce_ = f;
  proxyFn_ = nullptr;
}

void ForceInput::setCoupling(const CouplingDef& def, const ProxyTrajectory& proxy) {
  ++revision_;
  mode_ = Mode::Coupling;
  coupling_ = def;
  proxyFn_ = &proxy;
}

void ForceInput::setCoupling(const CouplingDef& def) {
  ++revision_;
  mode_ = Mode::Coupling;
  coupling_ = def;
  proxyFn_ = nullptr;
}

void ForceInput::holdProxy(const ProxyPose& pose) {
  // Bitwise, not ==: -0.0 and 0.0 give the same force, but a sleeping
  // stepper must wake on any change that a step could see.
  const bool same = std::memcmp(pose.position.data(), heldProxy_.position.data(), sizeof(double) * 3) == 0 &&
                    std::memcmp(pose.velocity.data(), heldProxy_.velocity.data(), sizeof(double) * 3) == 0;
  if (same) return;
  heldProxy_ = pose;
  ++revision_;
}

}  // namespace hemiroll::physics
