#include "engine/haptics/ForceClamp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace hemiroll::haptics {
namespace {

// Property: for any input, including NaN, Inf and huge values, the output is
// finite and never longer than the limit; NaN/Inf gives zero and the flag.
TEST(ForceClampTest, OutputIsFiniteAndWithinTheLimitForRandomInputs) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_real_distribution<double> exponent(-10.0, 308.0);
  const double specials[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::max(),
                             -std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min(), 0.0};
  auto component = [&] {
    const int k = kind(rng);
    if (k == 0) return specials[std::uniform_int_distribution<int>(0, 6)(rng)];
    if (k < 4) return unit(rng) * std::pow(10.0, exponent(rng));
    return 10.0 * unit(rng);
  };
  int nonFinite = 0, clamped = 0;
  for (int i = 0; i < 200000; ++i) {
    const Vec3 f(component(), component(), component());
    const double limit = (i % 7 == 0) ? 0.0 : 0.1 + 9.9 * std::abs(unit(rng));
    const ClampResult r = clampForce(f, limit);
    ASSERT_TRUE(r.force.allFinite()) << f.transpose();
    ASSERT_LE(r.force.norm(), limit) << f.transpose() << " limit " << limit;
    if (!f.allFinite()) {
      ASSERT_TRUE(r.nonFinite);
      ASSERT_EQ(r.force, Vec3::Zero());
      ++nonFinite;
    } else {
      ASSERT_FALSE(r.nonFinite);
      if (r.clamped) ++clamped;
    }
  }
  // The generator really reached both branches.
  EXPECT_GT(nonFinite, 1000);
  EXPECT_GT(clamped, 10000);
}

TEST(ForceClampTest, KeepsDirectionAndLeavesSmallForcesAlone) {
  const Vec3 small(0.3, -0.4, 0.0);
  EXPECT_EQ(clampForce(small, 1.0).force, small);
  EXPECT_FALSE(clampForce(small, 1.0).clamped);
  const ClampResult r = clampForce(Vec3(30.0, -40.0, 0.0), 2.0);
  EXPECT_TRUE(r.clamped);
  // 1e-14 relative: a scaling by one rounded ratio and at most 4 ulp-sized shrinks.
  EXPECT_NEAR(r.force.x(), 1.2, 1e-14);
  EXPECT_NEAR(r.force.y(), -1.6, 1e-14);
}

TEST(ForceClampTest, StepLimitBoundsTheChange) {
  const Vec3 out = limitForceStep(Vec3::Zero(), Vec3(3.0, 4.0, 0.0), 0.5);
  EXPECT_NEAR(out.norm(), 0.5, 1e-15);
  EXPECT_EQ(limitForceStep(Vec3::Zero(), Vec3(0.1, 0.0, 0.0), 0.5), Vec3(0.1, 0.0, 0.0));
}

}  // namespace
}  // namespace hemiroll::haptics
