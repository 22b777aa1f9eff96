#include "engine/haptics/devices/SimulatedHandDevice.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/haptics/ServoLoop.h"

namespace hemiroll::haptics {
namespace {

SimulatedHandDevice::Intent holdAt(const Vec3& p) { return {p, Vec3::Zero()}; }

TEST(SimulatedHandDeviceTest, AConstantForceDisplacesTheHandByForceOverStiffness) {
  const Vec3 rest(0.01, 0.0, 0.04);
  SimulatedHandDevice hand([&](double) { return holdAt(rest); });
  hand.sendForce(Vec3(0.0, 1.5, 0.0));
  DeviceReading r;
  for (int i = 1; i <= 2000; ++i) r = hand.read(i * 0.001);
  // Steady state of the damped spring (decay rate ~25 1/s, so e^-50 after 2 s);
  // 1e-9 m is far above the rounding of the fixed point.
  EXPECT_NEAR(r.position.y() - rest.y(), 1.5 / HandModelDef{}.stiffness, 1e-9);
  EXPECT_NEAR(r.position.x(), rest.x(), 1e-9);
  EXPECT_NEAR(r.velocity.norm(), 0.0, 1e-9);
}

TEST(SimulatedHandDeviceTest, FollowsItsIntentWithoutForce) {
  SimulatedHandDevice hand([](double t) {
    return SimulatedHandDevice::Intent{Vec3(0.01 * t, 0.0, 0.0), Vec3(0.01, 0.0, 0.0)};
  });
  DeviceReading r;
  for (int i = 1; i <= 1000; ++i) r = hand.read(i * 0.001);
  // A ramp is tracked with zero steady-state error (the damper sees the
  // intended velocity); 1e-6 m covers the sampling of the intent per sub-step.
  EXPECT_NEAR(r.position.x(), 0.01, 1e-6);
  EXPECT_NEAR(r.velocity.x(), 0.01, 1e-6);
}

// The whole haptic loop closed through the hand: engaged for 3 s while the
// hand means to circle the mass point; stable, no fault, the force is felt.
TEST(SimulatedHandDeviceTest, ClosesTheServoLoopStably) {
  constexpr double kPi = 3.141592653589793, r = 0.005, w = 2.0 * kPi;
  const auto intent = [=](double t) {
    return SimulatedHandDevice::Intent{Vec3(r * std::sin(w * t), r * (1.0 - std::cos(w * t)), 0.04),
                                       Vec3(r * w * std::cos(w * t), r * w * std::sin(w * t), 0.0)};
  };
  SimulatedHandDevice hand(intent);
  ServoLoopDef def;
  def.requestRealtime = false;
  ServoLoop loop(def, hand);
  ServoCommand engage;
  engage.kind = ServoCommandKind::Engage;
  loop.post(engage);
  loop.runHeadless(3000);
  ServoSnapshot s;
  ASSERT_TRUE(loop.latest(s));
  EXPECT_EQ(s.fault, SafetyFault::None) << safetyFaultName(s.fault);
  EXPECT_EQ(s.engagement, Engagement::Engaged);
  EXPECT_EQ(s.rampScale, 1.0);
  const double rendered = std::hypot(s.renderedForce[0], s.renderedForce[1], s.renderedForce[2]);
  EXPECT_GT(rendered, 0.01);
  EXPECT_LE(rendered, hand.spec().maxForce);
  // The rendered force pushed the hand off its intent.
  EXPECT_GT((hand.position() - intent(loop.time()).position).norm(), 1e-4);
}

}  // namespace
}  // namespace hemiroll::haptics
