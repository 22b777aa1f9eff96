// engine/analysis PhaseSegmenter: acceleration, steady precession and
// deceleration found at the times a constructed psi(t) puts them.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "engine/analysis/PhaseSegmenter.h"
#include "tests/analysis/support/Synthetic.h"

namespace hemiroll::analysis {
namespace {

// Rate: a ramp 0 -> W over [0, 12] s, W until 30 s, a ramp W -> 0 until 42 s,
// still until 45 s. psi is its integral (exact), sampled at 100 Hz.
constexpr double kRampUp = 12.0, kSteadyEnd = 30.0, kRampDown = 12.0, kEnd = 45.0;

double psiAt(double t, double w) {
  if (t <= kRampUp) return w * t * t / (2.0 * kRampUp);
  double psi = w * kRampUp / 2.0;
  if (t <= kSteadyEnd) return psi + w * (t - kRampUp);
  psi += w * (kSteadyEnd - kRampUp);
  const double s = std::min(t, kSteadyEnd + kRampDown) - kSteadyEnd;
  return psi + w * (s - s * s / (2.0 * kRampDown));
}

struct Samples {
  std::vector<double> t, psi;
};

Samples threePhases(double w) {
  Samples s;
  for (int i = 0; i <= 4500; ++i) s.t.push_back(0.01 * i), s.psi.push_back(psiAt(s.t.back(), w));
  return s;
}

// Where the ramps cross the band edge (1 - 0.25) |W| - 0.02 (PhaseDef's
// defaults), with W the median: the steady 18 s hold more than half the samples.
double edgeRate(double w) { return 0.75 * std::abs(w) - 0.02; }

void expectThreePhases(const Phases& p, double w, double tolerance) {
  ASSERT_TRUE(p.found) << p.reason;
  const double up = kRampUp * edgeRate(w) / std::abs(w);
  const double down = kSteadyEnd + kRampDown * (1.0 - edgeRate(w) / std::abs(w));
  EXPECT_NEAR(p.acceleration.start, 0.0, 1e-12);
  EXPECT_NEAR(p.steady.start, up, tolerance);
  EXPECT_NEAR(p.steady.end, down, tolerance);
  EXPECT_DOUBLE_EQ(p.acceleration.end, p.steady.start);
  EXPECT_DOUBLE_EQ(p.deceleration.start, p.steady.end);
  EXPECT_NEAR(p.deceleration.end, kEnd, 1e-9);
  EXPECT_NEAR(p.steadyRateMedian, w, 1e-3);
  EXPECT_NEAR(p.steadyRate, (psiAt(down, w) - psiAt(up, w)) / (down - up), 2e-3);
}

TEST(PhaseSegmenter, ThreeKnownPhasesAtTheirTimes) {
  // The boundaries lie 3.5 s inside the ramps, more than the rate filter's
  // half support (1.5 s slope + 1.5 s average), where the slope of a
  // quadratic psi and the average of a linear rate are exact: only the
  // 0.01 s sampling of the band edge remains.
  expectThreePhases(segmentPhases(threePhases(0.5).t, threePhases(0.5).psi), 0.5, 0.02);
  // Clockwise, as the paper's Omega < 0.
  const Samples cw = threePhases(-0.8);
  expectThreePhases(segmentPhases(cw.t, cw.psi), -0.8, 0.02);
}

TEST(PhaseSegmenter, NoisyAngleStillSegmentedWithinFiftyMilliseconds) {
  Samples s = threePhases(0.5);
  test::addNoise(s.psi, 0.005, 11);
  // The slope over 301 samples has a standard error of 0.005 / (0.01 sqrt(2.3e6))
  // = 3.3e-4 rad/s, less after the average; the ramps change by 0.042 rad/s per
  // second, so a boundary moves by under 8 ms per standard error: 50 ms is six of them.
  expectThreePhases(segmentPhases(s.t, s.psi), 0.5, 0.05);
}

TEST(PhaseSegmenter, WrappedAngleIsUnwrappedFirst) {
  Samples s = threePhases(1.5);
  for (double& a : s.psi) a = std::remainder(a, 2.0 * std::numbers::pi);
  expectThreePhases(segmentPhases(s.t, s.psi), 1.5, 0.02);
}

TEST(PhaseSegmenter, NoPrecessionIsNotFound) {
  std::vector<double> t, psi;
  for (int i = 0; i < 2000; ++i) t.push_back(0.01 * i), psi.push_back(0.3);
  const Phases p = segmentPhases(t, psi);
  EXPECT_FALSE(p.found);
  EXPECT_NE(p.reason.find("no steady precession"), std::string::npos) << p.reason;
  EXPECT_NE(p.reason.find("rad/s"), std::string::npos) << p.reason;
}

TEST(PhaseSegmenter, ShortOrNaNInputSaysWhy) {
  std::vector<double> t, psi;
  for (int i = 0; i < 200; ++i) t.push_back(0.01 * i), psi.push_back(0.5 * t.back());
  const Phases shortTrial = segmentPhases(t, psi);
  EXPECT_FALSE(shortTrial.found);
  EXPECT_NE(shortTrial.reason.find("needs 3 s"), std::string::npos) << shortTrial.reason;

  std::fill(psi.begin(), psi.end(), std::numeric_limits<double>::quiet_NaN());
  const Phases nan = segmentPhases(t, psi);
  EXPECT_FALSE(nan.found);
  EXPECT_NE(nan.reason.find("usable samples"), std::string::npos) << nan.reason;
  EXPECT_FALSE(segmentPhases({}, {}).found);
}

}  // namespace
}  // namespace hemiroll::analysis
