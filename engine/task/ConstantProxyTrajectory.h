#pragma once
// A proxy that stays where it is put: the `proxy = {x, y, z}` form of a
// scenario (a spring tether to a fixed point).

#include "engine/physics/ForceDrivenSystem.h"

namespace hemiroll::task {

class ConstantProxyTrajectory final : public physics::ProxyTrajectory {
 public:
  explicit ConstantProxyTrajectory(const physics::Vec3& position) { pose_.position = position; }
  physics::ProxyPose at(double) const override { return pose_; }

 private:
  physics::ProxyPose pose_;  // velocity stays zero
};

}  // namespace hemiroll::task
