// engine/autopilot/PlantModel: the planner's copy of the plant. That its
// rollouts end where a closed-loop play ends is AutopilotTest (the plant
// there is a PlantModel too, and the planner's predictions are checked
// against it); here: the clock on the servo grid, a reset that restores a
// state exactly, and a domain event reported when the proxy drags the mass
// point off the face.

#include "engine/autopilot/PlantModel.h"

#include <gtest/gtest.h>

#include <cstring>

namespace hemiroll::autopilot {
namespace {

using physics::Vec3;

TEST(PlantModel, TicksOnTheServoGridAndResetsExactly) {
  const physics::HemisphereParams params;
  PlantModel plant(params, physics::CouplingDef{}, 0.001);
  plant.reset(physics::ForceDrivenState::Zero(), 2.0);
  const Vec3 proxy(0.002, 0.0, params.radius), still = Vec3::Zero();
  for (int k = 0; k < 500; ++k) ASSERT_EQ(plant.tick(proxy, still), physics::DomainEvent::None);
  EXPECT_NEAR(plant.time(), 2.5, 1e-12);
  const physics::ForceDrivenState saved = plant.state();
  const double savedTime = plant.time();
  for (int k = 0; k < 500; ++k) plant.tick(proxy, still);
  plant.reset(saved, savedTime);
  EXPECT_EQ(plant.time(), savedTime);
  EXPECT_EQ(std::memcmp(plant.state().data(), saved.data(), sizeof(double) * 12), 0);
  // The same ticks from the same state: the same bits.
  PlantModel again(params, physics::CouplingDef{}, 0.001);
  again.reset(saved, savedTime);
  for (int k = 0; k < 300; ++k) {
    plant.tick(proxy, still);
    again.tick(proxy, still);
  }
  EXPECT_EQ(std::memcmp(plant.state().data(), again.state().data(), sizeof(double) * 12), 0);
}

TEST(PlantModel, AProxyFarOffTheFaceEndsInADomainEvent) {
  const physics::HemisphereParams params;
  PlantModel plant(params, physics::CouplingDef{}, 0.001);
  plant.reset(physics::ForceDrivenState::Zero(), 0.0);
  // 10 cm sideways: the spring (250 N/m, 25 N) drags the point past the rim.
  const Vec3 far(0.1, 0.0, params.radius);
  physics::DomainEvent event = physics::DomainEvent::None;
  for (int k = 0; k < 5000 && event == physics::DomainEvent::None; ++k) event = plant.tick(far, Vec3::Zero());
  EXPECT_NE(event, physics::DomainEvent::None);
}

}  // namespace
}  // namespace hemiroll::autopilot
