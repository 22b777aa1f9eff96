#include "engine/haptics/ForceSafety.h"

#include <gtest/gtest.h>

#include <functional>

#include <limits>

namespace hemiroll::haptics {
namespace {

constexpr double kDt = 0.001;

SafetyDef quickRamp() {
  SafetyDef def;
  def.engagement.rampTime = 0.01;  // 10 ticks, so the tests reach full force quickly
  def.maxForceRate = 1e6;          // the rate limit tested on its own below
  return def;
}

// Engaged at full scale, rendering a steady force.
ForceSafety engagedAtFullForce(const SafetyDef& def, const Vec3& force) {
  ForceSafety safety(def, DeviceSpec{});
  safety.engage();
  SafetyInputs in;
  in.desiredForce = force;
  for (int i = 0; i < 50; ++i) safety.update(in);
  return safety;
}

TEST(ForceSafetyTest, ClampsToTheDeviceLimit) {
  ForceSafety safety = engagedAtFullForce(quickRamp(), Vec3(10.0, 0.0, 0.0));
  EXPECT_NEAR(safety.lastForce().norm(), DeviceSpec{}.maxForce, 1e-12);
  EXPECT_TRUE(safety.lastClamped());
}

TEST(ForceSafetyTest, NoForceForAnInputOnlyDevice) {
  DeviceSpec mouse;
  mouse.hasForceOutput = false;
  ForceSafety safety(quickRamp(), mouse);
  safety.engage();
  SafetyInputs in;
  in.desiredForce = Vec3(1.0, 0.0, 0.0);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(safety.update(in), Vec3::Zero());
}

TEST(ForceSafetyTest, RateLimitSpreadsAStep) {
  SafetyDef def = quickRamp();
  def.engagement.rampTime = 0.0;  // no ramp: a step arrives at the rate limit
  def.maxForceRate = 100.0;       // 0.1 N per tick
  ForceSafety safety(def, DeviceSpec{});
  safety.engage();
  SafetyInputs in;
  in.desiredForce = Vec3(0.0, 2.0, 0.0);
  safety.update(in);  // engages
  const Vec3 first = safety.update(in);
  EXPECT_NEAR(first.norm(), 0.1, 1e-12);
  for (int i = 0; i < 18; ++i) safety.update(in);
  EXPECT_NEAR(safety.lastForce().y(), 1.9, 1e-12);  // 19 steps of 0.1 N; 1e-12: sums of 0.1
  safety.update(in);
  EXPECT_NEAR(safety.lastForce().y(), 2.0, 1e-12);
}

struct Trip {
  const char* what;
  void (*spoil)(SafetyInputs&);
  SafetyFault expected;
};

class ForceSafetyWatchdogTest : public ::testing::TestWithParam<Trip> {};

// Every watchdog takes the force from full to zero in the tick it fires,
// drops the engagement and latches the fault until cleared.
TEST_P(ForceSafetyWatchdogTest, ZeroesTheForceAtOnce) {
  ForceSafety safety = engagedAtFullForce(quickRamp(), Vec3(1.0, 0.0, 0.0));
  ASSERT_NEAR(safety.lastForce().x(), 1.0, 1e-12);
  SafetyInputs in;
  in.desiredForce = Vec3(1.0, 0.0, 0.0);
  GetParam().spoil(in);
  EXPECT_EQ(safety.update(in), Vec3::Zero()) << GetParam().what;
  EXPECT_EQ(safety.fault(), GetParam().expected);
  EXPECT_EQ(safety.engagement().state(), Engagement::Disengaged);
  // Latched: healthy inputs do not bring the force back.
  SafetyInputs healthy;
  healthy.desiredForce = Vec3(1.0, 0.0, 0.0);
  EXPECT_EQ(safety.update(healthy), Vec3::Zero());
  safety.clearFault();
  EXPECT_FALSE(safety.faulted());
}

INSTANTIATE_TEST_SUITE_P(
    AllWatchdogs, ForceSafetyWatchdogTest,
    ::testing::Values(
        Trip{"device error", [](SafetyInputs& in) { in.deviceError = true; }, SafetyFault::DeviceError},
        Trip{"velocity", [](SafetyInputs& in) { in.deviceVelocity = Vec3(3.0, 0.0, 0.0); }, SafetyFault::VelocityGuard},
        Trip{"nan velocity",
             [](SafetyInputs& in) { in.deviceVelocity.x() = std::numeric_limits<double>::quiet_NaN(); },
             SafetyFault::VelocityGuard},
        Trip{"energy", [](SafetyInputs& in) { in.injectedEnergy = 1.0; }, SafetyFault::EnergyInjection},
        Trip{"spin", [](SafetyInputs& in) { in.angularSpeed = 500.0; }, SafetyFault::RunawayRotation},
        Trip{"nan force", [](SafetyInputs& in) { in.desiredForce.y() = std::numeric_limits<double>::quiet_NaN(); },
             SafetyFault::NonFiniteForce},
        Trip{"inf force", [](SafetyInputs& in) { in.desiredForce.z() = std::numeric_limits<double>::infinity(); },
             SafetyFault::NonFiniteForce},
        Trip{"halted", [](SafetyInputs& in) { in.modelHalted = true; }, SafetyFault::ModelHalted},
        Trip{"overrun", [](SafetyInputs& in) { in.tickLateness = 0.05; }, SafetyFault::LoopOverrun},
        Trip{"teleport", [](SafetyInputs& in) { in.devicePosition.x() = 0.09; }, SafetyFault::PositionJump},
        Trip{"nan position",
             [](SafetyInputs& in) { in.devicePosition.z() = std::numeric_limits<double>::quiet_NaN(); },
             SafetyFault::PositionJump}));

// A late tick means a device held its last force that long: a stop where a
// force is rendered, nothing to make safe on a mouse (issue 27: a single
// 23 ms tick stopped mouse play).
TEST(ForceSafetyTest, ALateTickStopsAForceDeviceNotAMouse) {
  SafetyInputs late;
  late.tickLateness = 0.03;  // past the 20 ms limit
  ForceSafety desk(quickRamp(), DeviceSpec{});
  desk.update(late);
  EXPECT_EQ(desk.fault(), SafetyFault::LoopOverrun);
  DeviceSpec mouse;
  mouse.hasForceOutput = false;
  ForceSafety pointer(quickRamp(), mouse);
  pointer.update(late);
  EXPECT_EQ(pointer.fault(), SafetyFault::None);
  late.tickLateness = std::numeric_limits<double>::quiet_NaN();  // nor does a broken clock on a mouse
  pointer.update(late);
  EXPECT_EQ(pointer.fault(), SafetyFault::None);
  // Nor stale data (the autopilot's hand on a mouse, behind after a stall),
  // which a force device stops for.
  SafetyInputs stale;
  stale.deviceFresh = false;
  for (int k = 0; k < 50; ++k) pointer.update(stale);
  EXPECT_EQ(pointer.fault(), SafetyFault::None);
  ForceSafety fresh(quickRamp(), DeviceSpec{});
  for (int k = 0; k < 50; ++k) fresh.update(stale);
  EXPECT_EQ(fresh.fault(), SafetyFault::StaleDevice);
}

// A client that teleports 9 cm every tick while reporting zero velocity got
// past the velocity guard (issue 19). The position guard sees the path over
// 10 ticks: a steady 1.5 m/s hand, or a mouse's motion arriving once per
// 16 ms frame, stays inside it.
TEST(ForceSafetyTest, ThePositionGuardCatchesTeleportsNotHandsOrFramedMice) {
  const auto run = [](const std::function<Vec3(int)>& position) {
    ForceSafety safety(quickRamp(), DeviceSpec{});
    safety.engage();
    SafetyInputs in;
    for (int k = 0; k < 500 && !safety.faulted(); ++k) {
      in.devicePosition = position(k);  // deviceVelocity stays zero, as the client claims
      safety.update(in);
    }
    return safety.fault();
  };
  EXPECT_EQ(run([](int k) { return Vec3(k % 2 ? 0.09 : 0.0, 0.0, 0.0); }), SafetyFault::PositionJump);
  EXPECT_EQ(run([](int k) { return Vec3(0.0015 * k, 0.0, 0.0); }), SafetyFault::None);
  // 1 m/s delivered as 16 mm every 16th tick.
  EXPECT_EQ(run([](int k) { return Vec3(0.016 * (k / 16), 0.0, 0.0); }), SafetyFault::None);
  // A device without force output (the mouse) has no force to make safe: a
  // 5 cm flick in one frame does not stop the game.
  DeviceSpec mouse;
  mouse.hasForceOutput = false;
  ForceSafety safety(quickRamp(), mouse);
  SafetyInputs in;
  safety.update(in);
  in.devicePosition = Vec3(0.05, 0.0, 0.0);
  safety.update(in);
  EXPECT_EQ(safety.fault(), SafetyFault::None);
}

TEST(ForceSafetyTest, ForceOffIsImmediateAndTheRateLimitRestartsFromZero) {
  SafetyDef def = quickRamp();
  def.maxForceRate = 100.0;  // 0.1 N per tick
  ForceSafety safety = engagedAtFullForce(def, Vec3(2.0, 0.0, 0.0));
  ASSERT_NEAR(safety.lastForce().x(), 2.0, 1e-12);
  SafetyInputs in;
  in.desiredForce = Vec3(2.0, 0.0, 0.0);
  in.forceOff = true;
  EXPECT_EQ(safety.update(in), Vec3::Zero());
  EXPECT_FALSE(safety.faulted());
  in.forceOff = false;
  EXPECT_NEAR(safety.update(in).x(), 0.1, 1e-12);  // back at the rate limit, not as a 2 N step
}

TEST(ForceSafetyTest, StaleDataTripsAfterTheLimitNotBefore) {
  SafetyDef def = quickRamp();
  def.staleLimit = 0.010;
  ForceSafety safety = engagedAtFullForce(def, Vec3(1.0, 0.0, 0.0));
  SafetyInputs stale;
  stale.desiredForce = Vec3(1.0, 0.0, 0.0);
  stale.deviceFresh = false;
  // 10 stale ticks reach 10 ms (within rounding of the sum): still rendering.
  for (int i = 0; i < 9; ++i) ASSERT_NE(safety.update(stale), Vec3::Zero()) << i;
  int ticks = 9;
  while (!safety.faulted() && ticks < 12) {
    safety.update(stale);
    ++ticks;
  }
  EXPECT_EQ(safety.fault(), SafetyFault::StaleDevice);
  EXPECT_LE(ticks, 11);
  EXPECT_EQ(safety.lastForce(), Vec3::Zero());
}

TEST(ForceSafetyTest, AFreshSampleResetsTheStaleTimer) {
  ForceSafety safety = engagedAtFullForce(quickRamp(), Vec3(1.0, 0.0, 0.0));
  SafetyInputs stale, fresh;
  stale.deviceFresh = false;
  for (int round = 0; round < 5; ++round) {
    for (int i = 0; i < 8; ++i) safety.update(stale);
    safety.update(fresh);
  }
  EXPECT_FALSE(safety.faulted());
}

// A device profile's box (game/trial/DeviceProfiles): a position beyond it
// by more than the margin stops the force, on that tick; inside, nothing.
TEST(ForceSafetyTest, APositionOutsideTheProfilesWorkspaceStops) {
  SafetyDef def = quickRamp();
  def.workspaceHalfWidth = 0.08;
  def.workspaceHalfDepth = 0.035;
  def.workspaceHalfHeight = 0.06;
  def.workspaceMargin = 0.01;
  ForceSafety safety(def, DeviceSpec{});
  safety.engage();
  SafetyInputs in;
  in.desiredForce = Vec3(0.5, 0.0, 0.0);
  in.devicePosition = Vec3(0.0, 0.044, 0.0);  // 9 mm beyond the depth: within the margin
  for (int i = 0; i < 20; ++i) safety.update(in);
  EXPECT_FALSE(safety.faulted()) << safetyFaultName(safety.fault());
  in.devicePosition = Vec3(0.0, 0.046, 0.0);  // 11 mm beyond it (a slow 2 mm step: not a jump)
  EXPECT_EQ(safety.update(in), Vec3::Zero());
  EXPECT_EQ(safety.fault(), SafetyFault::OutsideWorkspace);
}

TEST(ForceSafetyTest, WithoutAProfileTheWorkspaceIsNotChecked) {
  ForceSafety safety(quickRamp(), DeviceSpec{});
  safety.engage();
  SafetyInputs in;
  in.devicePosition = Vec3(0.0, 0.0, 5.0);
  for (int i = 0; i < 20; ++i) safety.update(in);
  EXPECT_FALSE(safety.faulted()) << safetyFaultName(safety.fault());
}

// The continuous rating: held above it for longer than the limit stops the
// force; dipping below it starts the count again.
TEST(ForceSafetyTest, AForceHeldAboveTheContinuousRatingTooLongStops) {
  SafetyDef def = quickRamp();
  def.continuousForce = 1.0;
  def.aboveContinuousLimit = 0.1;  // 100 ticks
  ForceSafety safety(def, DeviceSpec{});
  safety.engage();
  SafetyInputs in;
  in.desiredForce = Vec3(2.0, 0.0, 0.0);  // within the 3 N clamp, above the 1 N rating
  int ticks = 0;
  while (!safety.faulted() && ticks < 1000) {
    safety.update(in);
    ++ticks;
  }
  EXPECT_EQ(safety.fault(), SafetyFault::ForceSaturated);
  // The ramp (10 ticks) passes 1 N on its 6th tick; the count starts on
  // the next tick (it judges the force already sent) and trips past 100.
  EXPECT_GE(ticks, 100);
  EXPECT_LE(ticks, 110);
  EXPECT_EQ(safety.lastForce(), Vec3::Zero());
}

TEST(ForceSafetyTest, DippingBelowTheContinuousRatingRestartsTheCount) {
  SafetyDef def = quickRamp();
  def.continuousForce = 1.0;
  def.aboveContinuousLimit = 0.1;
  ForceSafety safety(def, DeviceSpec{});
  safety.engage();
  SafetyInputs high, low;
  high.desiredForce = Vec3(2.0, 0.0, 0.0);
  low.desiredForce = Vec3(0.5, 0.0, 0.0);
  for (int round = 0; round < 5; ++round) {
    for (int i = 0; i < 80; ++i) safety.update(high);
    for (int i = 0; i < 3; ++i) safety.update(low);
  }
  EXPECT_FALSE(safety.faulted()) << safetyFaultName(safety.fault());
}

}  // namespace
}  // namespace hemiroll::haptics
