// game/research/sweep/PointMeasurement: one point run and measured. The paper's point
// from the static tilt is the run docs/FIGURES.md measured (a steady
// precession over the whole run, a helix with one loop per leaf); from rest
// at k = 16, Omega = -1 rad/s it tips over within half a second; the tilt
// formula agrees with the orientation of eq. (6).

#include "game/research/sweep/PointMeasurement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/analysis/PhaseSegmenter.h"
#include "engine/physics/Orientation.h"
#include "engine/script/SweepLoader.h"

namespace hemiroll::game {
namespace {

PointMeasurement measure(const std::string& source) {
  const SweepGrid grid(script::SweepLoader().loadSource(source, "s.lua"));
  return measurePoint(grid, grid.point(0));
}

TEST(PointMeasurement, ThePapersPointFromTheStaticTiltIsPaperLike) {
  const PointMeasurement m = measure("return { axes = { { param = 'k', values = { 8 } } } }");
  EXPECT_EQ(m.event, physics::DomainEvent::None);
  EXPECT_EQ(m.simulated, 35.0);
  ASSERT_TRUE(m.features.phases.found);
  // FIGURES.md: steady 0.6-34.1 s at -0.059 rad/s; arc -42.3 1/m; 15 loops,
  // 1.00 per leaf. Chaos makes long runs depend on the last bits (another
  // integrator or machine): features, not points, and a margin of a few %.
  EXPECT_GT(m.steadyFraction(), 0.9);
  EXPECT_NEAR(m.features.phases.steadyRate, -0.059, 0.005);
  EXPECT_LT(m.relativeSpread(), 0.25);
  EXPECT_NEAR(m.features.helix.arc.curvature, -42.3, 1.0);
  EXPECT_NEAR(m.features.loopsPerLeaf, 1.0, 0.02);
  EXPECT_TRUE(m.helixInSteadyPhase);
  EXPECT_TRUE(m.paperLike);
  EXPECT_NEAR(m.maxTilt, 0.58, 0.05);  // stays near the 33.4 degree start
  EXPECT_NEAR(m.meanRate, -0.059, 0.01);
  EXPECT_EQ(m.notes(), "");
}

TEST(PointMeasurement, FromRestAFastRoseTipsOver) {
  const PointMeasurement m =
      measure("return { start = 'rest', duration = 5, drive = { k = 16, Omega = -1 }, axes = { { param = 'g', values = { 9.81 } } } }");
  EXPECT_EQ(m.event, physics::DomainEvent::TippedOver);
  EXPECT_GT(m.eventTime, 0.1);
  EXPECT_LT(m.eventTime, 1.0);  // 0.39 s measured
  EXPECT_EQ(m.simulated, m.eventTime);
  EXPECT_NEAR(m.maxTilt, 0.5 * std::numbers::pi, 1e-6);  // the event state is at the rim
  EXPECT_FALSE(m.paperLike);
  EXPECT_EQ(m.notes().rfind("stopped by tipped_over", 0), 0u);
}

// A slow precession falls under the analysis' min_rate: no steady phase,
// with the reason; lowering min_rate in the spec finds one.
TEST(PointMeasurement, TheAnalysisThresholdsComeFromTheSpec) {
  const std::string axes = "axes = { { param = 'k', values = { 6 } } }, duration = 20, drive = { Omega = -0.3 }";
  const PointMeasurement strict = measure("return { " + axes + " }");
  EXPECT_FALSE(strict.features.phases.found);
  EXPECT_NE(strict.notes().find("below 0.05 rad/s"), std::string::npos);
  const PointMeasurement lenient = measure("return { analysis = { min_rate = 0.01 }, " + axes + " }");
  EXPECT_TRUE(lenient.features.phases.found);
}

TEST(PointMeasurement, TheTiltIsTheFaceNormalsAngleFromVertical) {
  for (const double u : {-1.2, -0.3, 0.0, 0.7})
    for (const double v : {-0.9, 0.2, 1.1})
      for (const double psi : {0.0, 2.0}) {
        const physics::Mat3 R = physics::makeOrientation(u, v, psi).R;
        EXPECT_NEAR(std::cos(u) * std::cos(v), R(2, 2), 1e-15);
      }
}

// The bound the recorder skips most rows' cosines by: never above the
// cosine (on a grid of angles well past the face's rim, both signs), and
// close to it over the tilts a sweep meets, or it would skip nothing.
TEST(PointMeasurement, TheTiltCosinesLowerBoundIsBelowItAndClose) {
  double worstClose = 0.0;
  for (double u = -3.0; u <= 3.0; u += 0.01)
    for (double v = -3.0; v <= 3.0; v += 0.0137) {
      const double exact = std::cos(u) * std::cos(v);
      const double bound = cosTiltLowerBound(u, v);
      ASSERT_LE(bound, exact + 1e-15) << "u = " << u << ", v = " << v;
      if (std::abs(u) <= 0.6 && std::abs(v) <= 0.6) worstClose = std::max(worstClose, exact - bound);
    }
  EXPECT_LT(worstClose, 1e-6);
  EXPECT_GT(worstClose, 0.0);  // a bound, not the cosine itself
  EXPECT_EQ(cosTiltLowerBound(std::nan(""), 0.1), -1.0);
  EXPECT_EQ(cosTiltLowerBound(0.1, INFINITY), -1.0);
}

TEST(PointMeasurement, SamplesAtAbout100Hz) {
  EXPECT_EQ(sampleEvery(0.001), 10);
  EXPECT_EQ(sampleEvery(0.0025), 4);
  EXPECT_EQ(sampleEvery(0.02), 1);
}

// The steady-phase thresholds default to the ones `hemiroll analyze` uses.
TEST(PointMeasurement, AnalysisDefaultsAreThoseOfTheAnalysis) {
  const analysis::PhaseDef phases;
  const task::SweepAnalysisDef sweep;
  EXPECT_EQ(sweep.minRate, phases.minRate);
  EXPECT_EQ(sweep.relativeBand, phases.relativeBand);
  EXPECT_EQ(sweep.absoluteBand, phases.absoluteBand);
}

}  // namespace
}  // namespace hemiroll::game
