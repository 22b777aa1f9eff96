#include "engine/haptics/VelocityEstimator.h"

#include <gtest/gtest.h>

namespace hemiroll::haptics {
namespace {

constexpr double kTick = 0.001;  // the servo period [s]

// A pointer moving at speed along x, sampled every samplePeriod, read every tick.
Vec3 velocityAfter(VelocityEstimator& e, double speed, double samplePeriod, double duration) {
  const int ticksPerSample = static_cast<int>(samplePeriod / kTick + 0.5);
  Vec3 v = Vec3::Zero();
  Vec3 p = Vec3::Zero();
  for (int k = 1; k <= static_cast<int>(duration / kTick + 0.5); ++k) {
    const double t = k * kTick;
    const bool sample = k % ticksPerSample == 0;
    if (sample) p = Vec3(speed * t, 0.0, 0.0);
    v = e.update(t, p, sample);
  }
  return v;
}

TEST(VelocityEstimatorTest, ASlowMouseGivesItsRealSpeedNotSpikes) {
  // 125 Hz mouse moving at 0.2 m/s, read at 1 kHz for 0.6 s.
  VelocityEstimator e;
  const double speed = 0.2;
  const int ticksPerSample = 8;
  double worst = 0.0;
  Vec3 p = Vec3::Zero();
  for (int k = 1; k <= 600; ++k) {
    const double t = k * kTick;
    const bool sample = k % ticksPerSample == 0;
    if (sample) p = Vec3(speed * t, 0.0, 0.0);
    const double v = e.update(t, p, sample).x();
    if (k > 500) worst = std::max(worst, std::abs(v - speed));
  }
  // Between samples the raw difference is held, so there is no ripple: after
  // 25 time constants the start-up transient is below 0.2 e^-25 ~ 3e-12 and
  // what is left is rounding.
  EXPECT_LT(worst, 1e-9);
}

TEST(VelocityEstimatorTest, FollowsWithTheStatedTimeConstant) {
  VelocityEstimator e;  // tau = 20 ms
  const Vec3 v = velocityAfter(e, 0.2, kTick, 0.020);
  // After one time constant of a step: 1 - e^-1 = 63 %, within a tick's worth.
  EXPECT_NEAR(v.x() / 0.2, 1.0 - std::exp(-1.0), 0.03);
}

TEST(VelocityEstimatorTest, APointerJumpIsClampedNotAFling) {
  VelocityEstimator e;
  e.update(0.0, Vec3::Zero(), true);
  double peak = 0.0;
  // 0.3 m in one tick (300 m/s raw), then still.
  for (int k = 1; k < 200; ++k) peak = std::max(peak, e.update(k * kTick, Vec3(0.3, 0, 0), k == 1).norm());
  EXPECT_LE(peak, VelocityFilterDef{}.maxSpeed);
}

TEST(VelocityEstimatorTest, StopsWhenSamplesStop) {
  VelocityEstimator e;
  velocityAfter(e, 0.2, kTick, 0.1);
  double t = 0.1;
  Vec3 v;
  for (int k = 0; k < 300; ++k) v = e.update(t += kTick, Vec3(0.02, 0, 0), false);
  // 0.3 s later: hold time 50 ms, then 12 time constants of decay.
  EXPECT_LT(v.norm(), 1e-5);
}

TEST(VelocityEstimatorTest, ResetStartsFromZeroAtTheNewPlace) {
  VelocityEstimator e;
  velocityAfter(e, 0.2, kTick, 0.1);
  e.reset(1.0, Vec3(0.05, 0.05, 0.0));
  EXPECT_EQ(e.velocity(), Vec3::Zero());
  EXPECT_EQ(e.update(1.001, Vec3(0.05, 0.05, 0.0), true), Vec3::Zero());
}

TEST(VelocityEstimatorTest, NonFinitePositionsAreIgnored) {
  VelocityEstimator e;
  velocityAfter(e, 0.2, kTick, 0.1);
  const Vec3 v = e.update(0.101, Vec3(std::nan(""), 0, 0), true);
  EXPECT_TRUE(v.allFinite());
  EXPECT_THROW(VelocityEstimator(VelocityFilterDef{0.0, 1.0, 0.05}), std::invalid_argument);
}

}  // namespace
}  // namespace hemiroll::haptics
