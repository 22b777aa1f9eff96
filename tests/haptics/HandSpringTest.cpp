// engine/haptics/HandSpring: the simulated hand between the mouse and the
// proxy, a mass on a spring and a damper, pushed by the coupling force.

#include "engine/haptics/HandSpring.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace hemiroll::haptics {
namespace {

// Held by a still pointer against a constant force, the hand settles where
// the spring balances it: F / k from the pointer. Semi-implicit Euler's
// fixed point solves k (pointer - x) + F = 0 exactly, so only the decay of
// the transient is left after 2 s (time constant 2 m / b = 0.04 s: e^-50).
TEST(HandSpringTest, SettlesOnThePointerOffsetByForceOverStiffness) {
  const HandSpringDef def;  // 0.3 kg, 300 N/m, 15 N s/m
  HandSpring hand(def);
  const Vec3 pointer(0.01, -0.02, 0.03);
  hand.reset(pointer);
  const Vec3 force(1.5, 0.0, -0.6);  // [N]
  for (int i = 0; i < 2000; ++i) hand.step(pointer, Vec3::Zero(), force, 0.001);
  const Vec3 expected = pointer + force / def.stiffness;  // 5 mm and 2 mm
  EXPECT_NEAR((hand.position() - expected).norm(), 0.0, 1e-12);
  EXPECT_NEAR(hand.velocity().norm(), 0.0, 1e-9);
}

// The stated stiffness, not another: a stiffer hand gives less.
TEST(HandSpringTest, AStifferHandGivesLessUnderTheSameForce) {
  HandSpringDef stiff;
  stiff.stiffness = 900.0;
  HandSpring soft{HandSpringDef{}}, hard{stiff};
  soft.reset(Vec3::Zero());
  hard.reset(Vec3::Zero());
  for (int i = 0; i < 2000; ++i) {
    soft.step(Vec3::Zero(), Vec3::Zero(), Vec3(0.9, 0, 0), 0.001);
    hard.step(Vec3::Zero(), Vec3::Zero(), Vec3(0.9, 0, 0), 0.001);
  }
  EXPECT_NEAR(soft.position().x(), 0.9 / 300.0, 1e-12);
  EXPECT_NEAR(hard.position().x(), 0.9 / 900.0, 1e-12);
}

// It rings as a mass on that spring does: underdamped (b = 15 < 2 sqrt(k m)
// = 19.0), its first overshoot comes half a damped period after a step,
// pi / omega_d with omega_d = sqrt(k/m - (b/2m)^2) = 19.4 rad/s: 0.162 s.
// The step is 1 ms, so the peak is found within a tick (plus Euler's own
// frequency error, under 1 % at h omega = 0.03).
TEST(HandSpringTest, RingsAtTheDampedFrequencyOfItsMassAndSpring) {
  const HandSpringDef def;
  HandSpring hand(def);
  hand.reset(Vec3::Zero());
  const Vec3 pointer(0.01, 0, 0);
  double peak = 0.0, peakTime = 0.0;
  for (int i = 1; i <= 400; ++i) {
    hand.step(pointer, Vec3::Zero(), Vec3::Zero(), 0.001);
    if (hand.position().x() > peak) {
      peak = hand.position().x();
      peakTime = i * 0.001;
    }
  }
  const double omegaD = std::sqrt(def.stiffness / def.mass - std::pow(def.damping / (2 * def.mass), 2));
  EXPECT_NEAR(peakTime, M_PI / omegaD, 0.002 + 0.01 * M_PI / omegaD);
  EXPECT_GT(peak, 0.01);  // it overshoots: the hand is a mass, not a filter
}

TEST(HandSpringTest, TheSameInputsGiveTheSameHandBitForBit) {
  HandSpring a, b;
  a.reset(Vec3::Zero());
  b.reset(Vec3::Zero());
  for (int i = 0; i < 1000; ++i) {
    const Vec3 pointer(0.01 * std::sin(i * 0.01), 0.005 * std::cos(i * 0.013), 0.0);
    const Vec3 force(0.3 * std::cos(i * 0.02), 0.1, 0.0);
    a.step(pointer, Vec3::Zero(), force, 0.001);
    b.step(pointer, Vec3::Zero(), force, 0.001);
  }
  EXPECT_EQ(a.position(), b.position());
  EXPECT_EQ(a.velocity(), b.velocity());
}

// A stall is not integrated as one long step (it would blow up) nor as a
// burst of sub-steps beyond maxGap; broken inputs leave the hand as it is.
TEST(HandSpringTest, ALongGapIsCutToMaxGapAndBrokenInputsAreIgnored) {
  HandSpring hand;
  hand.reset(Vec3::Zero());
  hand.step(Vec3(0.01, 0, 0), Vec3::Zero(), Vec3::Zero(), 1000.0);
  EXPECT_TRUE(hand.position().allFinite());
  EXPECT_LT(hand.position().x(), 0.02);
  const Vec3 before = hand.position();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  hand.step(Vec3(nan, 0, 0), Vec3::Zero(), Vec3::Zero(), 0.001);
  hand.step(Vec3::Zero(), Vec3::Zero(), Vec3(0, nan, 0), 0.001);
  hand.step(Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), nan);
  EXPECT_EQ(hand.position(), before);
}

TEST(HandSpringTest, ABadHandIsRefusedNamingTheField) {
  HandSpringDef d;
  EXPECT_EQ(validateHandSpring(d), "");
  d.mass = 0.0;
  EXPECT_NE(validateHandSpring(d).find("hand mass"), std::string::npos);
  d = {};
  d.stiffness = -1.0;
  EXPECT_NE(validateHandSpring(d).find("hand stiffness"), std::string::npos);
  d = {};
  d.damping = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(validateHandSpring(d).find("hand damping"), std::string::npos);
  d = {};
  d.stiffness = 1e6;  // maxStep sqrt(k/m) = 1.8: unstable
  EXPECT_NE(validateHandSpring(d).find("maxStep"), std::string::npos);
}

}  // namespace
}  // namespace hemiroll::haptics
