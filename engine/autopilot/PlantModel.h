#pragma once
// The autopilot's copy of the plant: the engine's own 12-state model, coupled
// to a proxy held for one tick at a time and stepped with RK4 at the servo
// period, exactly as the servo loop steps it (haptics/ServoLoop.cpp). A
// rollout through it therefore predicts a headless trial bit for bit, and a
// real-time one up to the hand-over jitter.

#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/Integrator.h"
#include "engine/physics/Stepper.h"

namespace hemiroll::autopilot {

class PlantModel {
 public:
  PlantModel(const physics::HemisphereParams& params, const physics::CouplingDef& coupling, double dt);
  PlantModel(const PlantModel&) = delete;
  PlantModel& operator=(const PlantModel&) = delete;

  void reset(const physics::ForceDrivenState& x, double t);
  // One servo tick with the proxy held at `position`, moving at `velocity`.
  physics::DomainEvent tick(const physics::Vec3& position, const physics::Vec3& velocity);

  const physics::ForceDrivenState& state() const { return stepper_.state(); }
  double time() const { return stepper_.time(); }
  const physics::ModelConstants& constants() const { return system_.dynamics().constants(); }
  double dt() const { return dt_; }

 private:
  physics::ForceDrivenSystem system_;
  physics::RungeKutta4<12> integrator_;
  physics::Stepper<12> stepper_;
  double dt_;
};

}  // namespace hemiroll::autopilot
