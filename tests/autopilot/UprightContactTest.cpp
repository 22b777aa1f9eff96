// engine/autopilot/UprightContact: the invariant the helix steers by (c_up).

#include "engine/autopilot/UprightContact.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/autopilot/Autopilot.h"

namespace hemiroll::autopilot {
namespace {

using physics::Vec3;

TEST(UprightContact, AStraightRollKeepsIt) {
  // Proxy held 1 cm off along x: the hemisphere rolls straight about y by
  // 0.24 rad and the contact moves 9.4 mm, but c_up stays at the start. On a
  // great circle the identity is exact; what is left is RK4's error.
  AutopilotDef def;
  PlantModel plant(def.params, def.coupling, def.dt);
  plant.reset(physics::ForceDrivenState::Zero(), 0.0);
  for (int k = 0; k < 3000; ++k) plant.tick(Vec3(0.01, 0.0, def.params.radius), Vec3::Zero());
  const UprightContact up = uprightContact(plant.constants(), plant.state());
  EXPECT_GT(plant.state()[physics::force_slot::u_a], 0.009);
  EXPECT_GT(up.tilt, 0.2);
  EXPECT_LT(up.point.norm(), 1e-9);
}

TEST(UprightContact, UprightItIsTheContactPoint) {
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  x[physics::force_slot::u_a] = 0.03;
  x[physics::force_slot::v_a] = -0.02;
  x[physics::force_slot::psi] = 1.0;
  const UprightContact up = uprightContact(physics::ModelConstants(physics::HemisphereParams{}), x);
  EXPECT_DOUBLE_EQ(up.point.x(), 0.03);
  EXPECT_DOUBLE_EQ(up.point.y(), -0.02);
  EXPECT_DOUBLE_EQ(up.tilt, 0.0);
}

}  // namespace
}  // namespace hemiroll::autopilot
