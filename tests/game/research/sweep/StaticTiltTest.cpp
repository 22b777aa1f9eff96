// game/research/sweep/StaticTilt: the hemisphere's static tilt for the mass point
// held at distance d. Checked against the equation it solves, the value
// levels/scenarios/rose_paper_equilibrium.lua types in (5 decimals), and
// the physics: held there, the hemisphere stays at rest; tilted the other
// way it falls.

#include "game/research/sweep/StaticTilt.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/physics/PrescribedDriveSystem.h"
#include "engine/physics/RoseDrive.h"

namespace hemiroll::game {
namespace {

double residual(const physics::HemisphereParams& p, double d, double t) {
  return p.pointMass * std::cos(t) * (d - p.radius * std::sin(t)) - 0.375 * p.radius * p.shellMass * std::sin(t);
}

TEST(StaticTilt, SolvesTheBalanceOfTorques) {
  for (const double d : {0.001, 0.004, 0.023, 0.039}) {
    for (const double mp : {0.05, 1.0, 20.0}) {
      physics::HemisphereParams p;
      p.pointMass = mp;
      const double t = staticTilt(p, d);
      EXPECT_GT(t, 0.0);
      EXPECT_LT(t, 0.5 * std::numbers::pi);
      // Bisection to the last bit: the residual changes sign across one ulp.
      EXPECT_GE(residual(p, d, t), 0.0) << d << " " << mp;
      EXPECT_LE(residual(p, d, std::nextafter(t, 2.0)), 0.0) << d << " " << mp;
    }
  }
}

TEST(StaticTilt, ThePapersStartIsTheScenariosTilt) {
  // rose_paper_equilibrium.lua: u_o = -0.58271 for p(0) = r1 + r2 = 2.3 cm.
  EXPECT_NEAR(staticTilt(physics::HemisphereParams{}, 0.023), 0.58271, 5e-6);
}

TEST(StaticTilt, NoOffsetOrNoTorqueMeansUpright) {
  physics::HemisphereParams p;
  EXPECT_EQ(staticTilt(p, 0.0), 0.0);
  p.pointMass = 0.0;
  EXPECT_EQ(staticTilt(p, 0.02), 0.0);
  p = {};
  p.gravity = 0.0;
  EXPECT_EQ(staticTilt(p, 0.02), 0.0);
}

// At the tilt, with the point held (Omega = 0), the body's angular
// acceleration vanishes to round-off; at the opposite tilt it does not.
TEST(StaticTilt, IsAnEquilibriumOfThePrescribedDrive) {
  physics::HemisphereParams p;
  p.pointMass = 0.7;
  p.shellMass = 0.3;
  physics::RoseDef rose;
  rose.omega = 0.0;
  const physics::RoseDrive held(rose);
  const physics::PrescribedDriveSystem system(p, held);
  const double t = staticTilt(p, rose.r1 + rose.r2);
  physics::BodyState x = physics::BodyState::Zero(), dx;
  x[physics::body_slot::u_o] = -t;
  system.derivative(0.0, x, dx);
  const double scale = p.gravity / p.radius;  // the size of each torque term / inertia
  EXPECT_LT(dx.head<3>().norm(), 1e-12 * scale);  // a few eps of g/R (PrescribedDriveSystemTest)
  x[physics::body_slot::u_o] = t;
  system.derivative(0.0, x, dx);
  EXPECT_GT(dx.head<3>().norm(), 1e-2 * scale);
}

}  // namespace
}  // namespace hemiroll::game
