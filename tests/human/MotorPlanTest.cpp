// engine/human/MotorPlan: submovements blend on the minimum-jerk profile,
// arrive when their duration ends, and never outrun the hand's speed limit;
// a stir goes round at its radius and pace.

#include "engine/human/MotorPlan.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hemiroll::human {
namespace {

using physics::Vec2;
using physics::Vec3;

TEST(MotorPlan, AHoldArrivesWhenItsDurationEndsAndStartsAndStopsAtRest) {
  MotorPlan plan;
  plan.reset(Vec3(0.0, 0.0, 0.04));
  Movement m;
  m.centre = Vec2(0.01, -0.005);
  plan.start(m, 0.25);
  plan.advance(0.001, 1.0);
  const double firstSpeed = plan.velocity().norm();
  double peak = 0.0;
  for (int i = 1; i < 250; ++i) {
    plan.advance(0.001, 1.0);
    peak = std::max(peak, plan.velocity().norm());
  }
  EXPECT_NEAR((plan.position().head<2>() - m.centre).norm(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(plan.position().z(), 0.04);
  // Minimum jerk: starts from rest, peaks at 1.875 x the mean speed mid-way.
  const double mean = m.centre.norm() / 0.25;
  EXPECT_LT(firstSpeed, 0.01 * mean);
  EXPECT_NEAR(peak, 1.875 * mean, 0.01 * mean);
  plan.advance(0.001, 1.0);
  EXPECT_LT(plan.velocity().norm(), 1e-9);
}

TEST(MotorPlan, TheHandNeverMovesFasterThanItsSpeedLimit) {
  MotorPlan plan;
  plan.reset(Vec3::Zero());
  Movement far;
  far.centre = Vec2(0.2, 0.0);  // 20 cm in a quarter of a second wants 1.5 m/s at its peak
  plan.start(far, 0.25);
  for (int i = 0; i < 1000; ++i) {
    plan.advance(0.001, 0.5);
    EXPECT_LE(plan.velocity().norm(), 0.5 + 1e-9) << "tick " << i;
  }
  EXPECT_NEAR(plan.position().x(), 0.2, 1e-9);  // it still gets there, later
}

TEST(MotorPlan, AStirGoesRoundItsCentreAtItsRadiusAndPace) {
  MotorPlan plan;
  plan.reset(Vec3::Zero());
  Movement stir;
  stir.kind = Movement::Kind::Stir;
  stir.centre = Vec2(0.002, 0.0);
  stir.radius = 0.003;
  stir.rate = M_PI;
  plan.start(stir, 0.25);
  for (int i = 0; i < 500; ++i) plan.advance(0.001, 1.0);  // blended in
  double minR = 1.0, maxR = 0.0;
  double turned = 0.0;
  Vec2 before = plan.position().head<2>() - stir.centre;
  for (int i = 0; i < 2000; ++i) {  // 2 s: one turn at half a turn a second
    plan.advance(0.001, 1.0);
    const Vec2 r = plan.position().head<2>() - stir.centre;
    minR = std::min(minR, r.norm());
    maxR = std::max(maxR, r.norm());
    turned += std::atan2(before.x() * r.y() - before.y() * r.x(), before.dot(r));
    before = r;
  }
  EXPECT_NEAR(minR, 0.003, 1e-9);
  EXPECT_NEAR(maxR, 0.003, 1e-9);
  EXPECT_NEAR(turned, 2.0 * M_PI, 1e-6);  // anticlockwise, one turn
}

TEST(MotorPlan, ANewCorrectionStartsFromWhereTheHandIsNotFromWhereItWasGoing) {
  MotorPlan plan;
  plan.reset(Vec3::Zero());
  Movement a;
  a.centre = Vec2(0.01, 0.0);
  plan.start(a, 0.25);
  for (int i = 0; i < 125; ++i) plan.advance(0.001, 1.0);  // half way
  const Vec3 here = plan.position();
  Movement b;
  b.centre = Vec2(0.0, 0.01);
  plan.start(b, 0.25);
  plan.advance(0.001, 1.0);
  EXPECT_LT((plan.position() - here).norm(), 1e-4);  // no jump
}

}  // namespace
}  // namespace hemiroll::human
