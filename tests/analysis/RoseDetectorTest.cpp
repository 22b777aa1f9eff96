// engine/analysis RoseDetector: the paper's rose (eqs. 49-50) reported with
// the leaves and radii it was built with; no rose where there is none.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "engine/analysis/RoseDetector.h"
#include "tests/analysis/support/Synthetic.h"

namespace hemiroll::analysis {
namespace {

using test::Planar;

constexpr double kR1 = 0.015, kR2 = 0.008, kOmega = -std::numbers::pi / 10.0;  // the paper's Sec. 5

// Noise-free tolerance on the radii: the 0.05 s (7-sample) smoothing shrinks
// the fast circle by 1 - sin(7 a / 2) / (7 sin(a / 2)), a = k |Omega| dt:
// 0.4 % of r2 at k = 14, less for smaller k (RoseDetector.h); the parabolic
// extrema add ~1e-4. 0.5 % of r2 = 40 um covers both.
constexpr double kRadiusTolerance = 0.005 * kR2;

TEST(RoseDetector, PaperRoseHasKPlusOneLeavesForEveryK) {
  for (int k = 7; k <= 14; ++k) {
    SCOPED_TRACE("k = " + std::to_string(k));
    const Planar p = test::rose(kR1, kR2, k, kOmega, 35.0, 100.0);
    const RoseFeatures r = detectRose(p.t, p.x, p.y);
    ASSERT_TRUE(r.found) << r.reason;
    EXPECT_EQ(r.leaves, k + 1);
    // At every minimum arg(p) = phi exactly, so the leaf angles sum to the
    // turn of phi: only the extrema's sub-sample placement (~1e-4 rad) remains.
    EXPECT_NEAR(r.leavesPerCycle, k + 1, 0.01 * (k + 1) / 9.0);
    EXPECT_NEAR(r.leafRadius.value, kR2, kRadiusTolerance);
    EXPECT_NEAR(r.outerRadius.value, kR1 + kR2, kRadiusTolerance);
    EXPECT_NEAR(r.innerRadius.value, kR1 - kR2, kRadiusTolerance);
    EXPECT_LT(r.leafRadius.spread, 1e-5);
    EXPECT_EQ(r.sense, -1);  // Omega < 0: the leaves advance clockwise
    // 35 s is 1.75 turns of phi: exactly one closed cycle, with k + 1 leaves in it.
    ASSERT_EQ(r.leavesPerClosedCycle.size(), 1u);
    EXPECT_EQ(r.leavesPerClosedCycle[0], k + 1);
    // The span is whole leaves: leafCount periods of 2 pi / ((k + 1) |Omega|).
    const double leafPeriod = 2.0 * std::numbers::pi / ((k + 1) * std::abs(kOmega));
    EXPECT_NEAR(r.leafPeriod.value, leafPeriod, 0.01);
    EXPECT_NEAR(r.span.duration(), r.leafCount * leafPeriod, 0.02);
    // The first and last whole leaves: a minimum counts once rho has risen by
    // the hysteresis (30 % of its range) after it, which takes under half a leaf.
    EXPECT_LT(r.span.start, leafPeriod);
    EXPECT_GT(r.span.end, 35.0 - 1.5 * leafPeriod);
    EXPECT_NEAR(r.cycles, r.leafCount / (k + 1.0), 0.01);
    EXPECT_GT(r.confidence, 0.99);
  }
}

TEST(RoseDetector, NoisyRoseAt100HzKeepsItsLeavesAndRadii) {
  // 0.1 mm of white noise per axis (three times a PHANToM's resolution).
  // Smoothed over 7 samples it is 0.04 mm; the extrema pick up about that
  // much outwards, so the leaf and outer radii may be biased by ~0.04 mm:
  // 2 % of r2 (0.16 mm) is four times that.
  for (int k : {8, 14}) {
    for (unsigned seed : {1u, 2u, 3u}) {
      SCOPED_TRACE("k = " + std::to_string(k) + ", seed " + std::to_string(seed));
      Planar p = test::rose(kR1, kR2, k, kOmega, 35.0, 100.0);
      test::addNoise(p.x, 1e-4, seed);
      test::addNoise(p.y, 1e-4, seed + 100);
      const RoseFeatures r = detectRose(p.t, p.x, p.y);
      ASSERT_TRUE(r.found) << r.reason;
      EXPECT_EQ(r.leaves, k + 1);
      EXPECT_NEAR(r.leafRadius.value, kR2, 0.02 * kR2);
      EXPECT_NEAR(r.outerRadius.value, kR1 + kR2, 0.02 * kR2);
    }
  }
}

TEST(RoseDetector, OffCentreRoseOverOneCycleFindsItsCentre) {
  // A human's rose need not be centred on the face, nor last longer than a cycle.
  Planar p = test::rose(0.012, 0.006, 10, 2.0 * std::numbers::pi / 20.0, 20.0, 100.0);
  for (double& x : p.x) x += 0.003;
  for (double& y : p.y) y -= 0.002;
  const RoseFeatures r = detectRose(p.t, p.x, p.y);
  ASSERT_TRUE(r.found) << r.reason;
  EXPECT_EQ(r.leaves, 11);
  EXPECT_EQ(r.sense, 1);
  // The circle through ten tips of equal radius passes through them exactly.
  EXPECT_NEAR(r.centreX, 0.003, 1e-5);
  EXPECT_NEAR(r.centreY, -0.002, 1e-5);
  EXPECT_NEAR(r.leafRadius.value, 0.006, 0.005 * 0.006);
}

TEST(RoseDetector, DenseInputAndADropoutInTheMiddle) {
  Planar p = test::rose(kR1, kR2, 8, kOmega, 35.0, 1000.0);  // 1 kHz, as `hemiroll sim` at 1 ms
  for (std::size_t i = 12000; i < 13000; ++i) p.x[i] = std::numeric_limits<double>::quiet_NaN();
  const RoseFeatures r = detectRose(p.t, p.x, p.y);
  ASSERT_TRUE(r.found) << r.reason;
  EXPECT_EQ(r.leaves, 9);
  EXPECT_GT(r.span.start, 13.0);  // the longer piece after the 1 s hole
}

TEST(RoseDetector, CircleWithoutLeavesIsNotARose) {
  const Planar p = test::rose(0.015, 0.0, 8, kOmega, 35.0, 100.0);
  const RoseFeatures r = detectRose(p.t, p.x, p.y);
  EXPECT_FALSE(r.found);
  EXPECT_NE(r.reason.find("varies by only"), std::string::npos) << r.reason;
}

TEST(RoseDetector, StraightLineIsNotARose) {
  std::vector<double> t, x, y;
  for (int i = 0; i <= 2000; ++i) t.push_back(0.01 * i), x.push_back(0.001 * t.back()), y.push_back(-0.0005 * t.back());
  const RoseFeatures r = detectRose(t, x, y);
  EXPECT_FALSE(r.found);
  EXPECT_NE(r.reason.find("no rose"), std::string::npos) << r.reason;
}

TEST(RoseDetector, NoiseOnlyIsNotARose) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    std::vector<double> t, x(3000, 0.0), y(3000, 0.0);
    for (int i = 0; i < 3000; ++i) t.push_back(0.01 * i);
    test::addNoise(x, 0.005, seed);
    test::addNoise(y, 0.005, seed + 50);
    const RoseFeatures r = detectRose(t, x, y);
    EXPECT_FALSE(r.found) << "seed " << seed << ": " << r.leaves << " leaves";
    EXPECT_FALSE(r.reason.empty());
  }
}

TEST(RoseDetector, LeavesAroundTheCentreAreNotARose) {
  // r2 > r1: each leaf encloses the centre and the pattern turns backwards.
  const Planar p = test::rose(0.004, 0.012, 8, kOmega, 35.0, 100.0);
  const RoseFeatures r = detectRose(p.t, p.x, p.y);
  EXPECT_FALSE(r.found);
  EXPECT_NE(r.reason.find("do not go round the centre"), std::string::npos) << r.reason;
}

TEST(RoseDetector, EmptyConstantAndNaNInputSayWhy) {
  EXPECT_NE(detectRose({}, {}, {}).reason.find("usable samples"), std::string::npos);
  std::vector<double> t, still(500, 0.01), nan(500, std::numeric_limits<double>::quiet_NaN());
  for (int i = 0; i < 500; ++i) t.push_back(0.01 * i);
  EXPECT_NE(detectRose(t, still, still).reason.find("does not move"), std::string::npos);
  const RoseFeatures r = detectRose(t, nan, still);
  EXPECT_FALSE(r.found);
  EXPECT_TRUE(std::isfinite(r.leafRadius.value) && std::isfinite(r.centreX));
}

}  // namespace
}  // namespace hemiroll::analysis
