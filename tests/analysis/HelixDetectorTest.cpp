// engine/analysis HelixDetector: a circular arc with loops (a trochoid)
// gives back its curvature, loop count and spacing; a line, a plain arc,
// wiggles and noise give "not found" with the reason.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "engine/analysis/HelixDetector.h"
#include "tests/analysis/support/Synthetic.h"

namespace hemiroll::analysis {
namespace {

using test::Planar;

// A 5 cm arc drifted along at 2 mm/s, loops of 2 mm at 0.45 Hz (the rose's
// leaf rate; 5.7 mm/s around the loop > 2 mm/s drift: true loops), 30 s at 100 Hz.
constexpr double kArcRadius = 0.05, kSpeed = 0.002, kLoopRadius = 0.002, kLoopRate = 2.0 * std::numbers::pi * 0.45;
constexpr double kDuration = 30.0;

// The point moves backwards (mid-loop) when the loop's velocity opposes the
// arc's tangent: (loopRate - speed / radius) t + phase = pi (mod 2 pi).
// With phase 0 that is t_n = (2n + 1) pi / (loopRate - beta): 13 instants in
// 30 s, the first at 1.13 s and the last at 28.2 s, none near an end.
constexpr double kBeta = kSpeed / kArcRadius;
constexpr double kLoopSpacing = 2.0 * std::numbers::pi / (kLoopRate - kBeta);  // 2.254 s

void expectTrochoid(const HelixFeatures& h, double sign) {
  ASSERT_TRUE(h.arc.found) << h.arc.reason;
  // The one-period moving average shrinks the arc's radius by
  // sinc(beta P / 2) = 1 - 3e-4 and leaves < 0.5 % of the loops (a window
  // within half a sample of the period): 1 % on the curvature covers both.
  EXPECT_NEAR(h.arc.curvature, sign * 20.0, 0.2);
  EXPECT_NEAR(h.arc.radius, kArcRadius, 0.01 * kArcRadius);
  EXPECT_NEAR(h.arc.driftSpeed, kSpeed, 0.01 * kSpeed);
  // The low-passed trace spans the run less one loop period.
  EXPECT_NEAR(h.arc.sweptAngle, sign * kBeta * (kDuration - 1.0 / 0.45), 0.01 * kBeta * kDuration);
  ASSERT_TRUE(h.loops.found) << h.loops.reason;
  EXPECT_EQ(h.loops.count, 13);
  EXPECT_EQ(h.loops.sense, sign > 0 ? 1 : -1);
  // Crossings are interpolated between 10 ms samples: within 5 ms each.
  EXPECT_NEAR(h.loops.spacingTime.value, kLoopSpacing, 0.005);
  EXPECT_LT(h.loops.spacingTime.spread, 0.005);
  ASSERT_EQ(h.loops.times.size(), 13u);
  EXPECT_NEAR(h.loops.times.front(), kLoopSpacing / 2.0, 0.005);
  // Along the arc a loop period is speed * spacing = 4.5 mm (1 %: the low-pass' shrinkage and sampling).
  EXPECT_NEAR(h.loops.spacingArc.value, kSpeed * kLoopSpacing, 0.01 * kSpeed * kLoopSpacing);
}

TEST(HelixDetector, TrochoidGivesItsCurvatureLoopsAndSpacing) {
  const Planar p = test::trochoidArc(kArcRadius, kSpeed, kLoopRadius, kLoopRate, 0.0, kDuration, 100.0, 0.01, -0.02);
  const HelixFeatures h = detectHelix(p.t, p.x, p.y);
  expectTrochoid(h, 1.0);
  EXPECT_NEAR(h.arc.centreX, 0.01, 1e-4);
  EXPECT_NEAR(h.arc.centreY, -0.02, 1e-4);
}

TEST(HelixDetector, ClockwiseTrochoidHasNegativeCurvature) {
  // Mirrored (y -> -y): the arc turns clockwise and so do the loops.
  Planar p = test::trochoidArc(kArcRadius, kSpeed, kLoopRadius, kLoopRate, 0.0, kDuration, 100.0);
  for (double& y : p.y) y = -y;
  expectTrochoid(detectHelix(p.t, p.x, p.y), -1.0);
}

TEST(HelixDetector, NoisyTrochoidKeepsItsLoops) {
  // 20 um of noise per axis: after the light smoothing the velocity's noise
  // (~0.5 mm/s) stays far below the slowest speed on a loop (3.7 mm/s), so
  // no loop is split or lost.
  Planar p = test::trochoidArc(kArcRadius, kSpeed, kLoopRadius, kLoopRate, 0.0, kDuration, 100.0);
  test::addNoise(p.x, 2e-5, 5);
  test::addNoise(p.y, 2e-5, 6);
  const HelixFeatures h = detectHelix(p.t, p.x, p.y);
  ASSERT_TRUE(h.loops.found) << h.loops.reason;
  EXPECT_EQ(h.loops.count, 13);
  EXPECT_NEAR(h.arc.curvature, 20.0, 0.4);
}

TEST(HelixDetector, WigglesAreNotLoops) {
  // A curtate trochoid: 0.5 mm at 0.45 Hz is 1.4 mm/s < 2 mm/s drift.
  const Planar p = test::trochoidArc(kArcRadius, kSpeed, 0.0005, kLoopRate, 0.0, kDuration, 100.0);
  const HelixFeatures h = detectHelix(p.t, p.x, p.y);
  EXPECT_TRUE(h.arc.found) << h.arc.reason;
  EXPECT_FALSE(h.loops.found);
  EXPECT_NE(h.loops.reason.find("wiggle"), std::string::npos) << h.loops.reason;
}

TEST(HelixDetector, PlainArcHasNoLoops) {
  const Planar p = test::trochoidArc(kArcRadius, kSpeed, 0.0, kLoopRate, 0.0, kDuration, 100.0);
  const HelixFeatures h = detectHelix(p.t, p.x, p.y);
  EXPECT_TRUE(h.arc.found) << h.arc.reason;
  EXPECT_NEAR(h.arc.curvature, 20.0, 0.2);
  EXPECT_FALSE(h.loops.found);
  EXPECT_NE(h.loops.reason.find("no loops"), std::string::npos) << h.loops.reason;
}

TEST(HelixDetector, StraightLineIsNotCurvedAndHasNoLoops) {
  std::vector<double> t, x, y;
  for (int i = 0; i <= 3000; ++i) t.push_back(0.01 * i), x.push_back(0.002 * t.back()), y.push_back(0.001 * t.back());
  const HelixFeatures h = detectHelix(t, x, y);
  EXPECT_FALSE(h.arc.found);
  EXPECT_NE(h.arc.reason.find("straight"), std::string::npos) << h.arc.reason;
  EXPECT_FALSE(h.loops.found);
  EXPECT_NE(h.loops.reason.find("no loops"), std::string::npos) << h.loops.reason;
  EXPECT_NEAR(h.arc.driftSpeed, std::hypot(0.002, 0.001), 1e-9);
}

TEST(HelixDetector, NoiseOnlyHasNoLoops) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    std::vector<double> t, x(3000, 0.0), y(3000, 0.0);
    for (int i = 0; i < 3000; ++i) t.push_back(0.01 * i);
    test::addNoise(x, 0.001, seed);
    test::addNoise(y, 0.001, seed + 10);
    const HelixFeatures h = detectHelix(t, x, y);
    EXPECT_FALSE(h.loops.found) << "seed " << seed;
    EXPECT_NE(h.loops.reason.find("no clear period"), std::string::npos) << h.loops.reason;
  }
}

TEST(HelixDetector, EmptyOrNaNInputSaysWhy) {
  const HelixFeatures empty = detectHelix({}, {}, {});
  EXPECT_FALSE(empty.arc.found);
  EXPECT_FALSE(empty.loops.found);
  EXPECT_NE(empty.loops.reason.find("usable samples"), std::string::npos);
  std::vector<double> t, nan(100, std::numeric_limits<double>::quiet_NaN());
  for (int i = 0; i < 100; ++i) t.push_back(0.01 * i);
  const HelixFeatures h = detectHelix(t, nan, nan);
  EXPECT_FALSE(h.arc.found);
  EXPECT_TRUE(std::isfinite(h.arc.curvature) && std::isfinite(h.loops.spacingTime.value));
}

}  // namespace
}  // namespace hemiroll::analysis
