#include "engine/autopilot/PlantModel.h"

namespace hemiroll::autopilot {

PlantModel::PlantModel(const physics::HemisphereParams& params, const physics::CouplingDef& coupling, double dt)
    : system_(params), stepper_(system_, integrator_, physics::ForceDrivenState::Zero()), dt_(dt) {
  system_.setCoupling(coupling);
}

void PlantModel::reset(const physics::ForceDrivenState& x, double t) { stepper_.reset(x, t); }

physics::DomainEvent PlantModel::tick(const physics::Vec3& position, const physics::Vec3& velocity) {
  physics::ProxyPose pose;
  pose.position = position;
  pose.velocity = velocity;
  system_.holdProxy(pose);
  return stepper_.advance(dt_).event;
}

}  // namespace hemiroll::autopilot
