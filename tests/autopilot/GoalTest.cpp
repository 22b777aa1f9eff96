// engine/autopilot/Goal: the bands as the autopilot measures them (the judge's
// comparison, psi modulo 2 pi) and the forbidden zones.

#include "engine/autopilot/Goal.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hemiroll::autopilot {
namespace {

using physics::Vec3;

TEST(Goal, ErrorIsTheWorstBandAndPsiWraps) {
  Goal g;
  g.set[11] = true;
  g.target[11] = M_PI - 0.05;
  g.tolerance[11] = 0.1;
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  x[11] = -M_PI + 0.02;  // 0.07 from the target across the seam
  EXPECT_NEAR(normalisedError(g, x), 0.7, 1e-12);
  g.omegaNormSet = true;
  g.omegaNormTolerance = 0.01;
  x[6] = 0.02;
  EXPECT_NEAR(normalisedError(g, x), 2.0, 1e-12);
}

TEST(Goal, ZonesKnowTheirEdge) {
  Zone circle;
  circle.centre = {0.01, 0.0};
  circle.radius = 0.002;
  EXPECT_NEAR(circle.clearance(physics::Vec2(0.0, 0.0)), 0.008, 1e-15);
  EXPECT_NEAR(circle.clearance(physics::Vec2(0.01, 0.001)), -0.001, 1e-15);
  Zone box;
  box.circle = false;
  box.min = {0.0, 0.0};
  box.max = {0.01, 0.02};
  EXPECT_NEAR(box.clearance(physics::Vec2(0.013, 0.024)), 0.005, 1e-15);  // 3-4-5 from the corner
  EXPECT_NEAR(box.clearance(physics::Vec2(0.002, 0.01)), -0.002, 1e-15);  // nearest side 2 mm away
  Goal g;
  g.zones[0] = circle;
  g.zoneCount = 1;
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  EXPECT_FALSE(inForbiddenZone(g, x));
  x[physics::force_slot::u_a] = 0.0095;
  EXPECT_TRUE(inForbiddenZone(g, x));
}

}  // namespace
}  // namespace hemiroll::autopilot
