// engine/analysis TrialAnalyzer: phases first, then rose and helix over the
// steady phase, or over the whole trial with a note.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <numbers>
#include <vector>

#include "engine/analysis/TrialAnalyzer.h"
#include "tests/analysis/support/Synthetic.h"

namespace hemiroll::analysis {
namespace {

struct Trial {
  test::Planar mass, contact;
  std::vector<double> psi;
  TrialSamples samples() const { return {mass.t, mass.x, mass.y, contact.x, contact.y, psi}; }
};

// 40 s: psi turns at 0.3 rad/s from 10 s to 30 s and stands still before and
// after; a 9-leaf rose on the face and loops at the leaf rate on the plane.
Trial makeTrial(bool precessing) {
  Trial trial;
  const double omega = -std::numbers::pi / 10.0;
  trial.mass = test::rose(0.015, 0.008, 8, omega, 40.0, 100.0);
  const double leafRate = 9.0 * std::abs(omega);
  trial.contact = test::trochoidArc(0.05, 0.002, 0.002, leafRate, 0.0, 40.0, 100.0);
  for (double t : trial.mass.t) trial.psi.push_back(precessing ? 0.3 * std::clamp(t - 10.0, 0.0, 20.0) : 0.0);
  return trial;
}

TEST(TrialAnalyzer, RoseAndHelixMeasuredOverTheSteadyPhase) {
  const TrialFeatures f = analyzeTrial(makeTrial(true).samples());
  ASSERT_TRUE(f.phases.found) << f.phases.reason;
  // Steps in the rate, smoothed over 3 s + 3 s: the band edge (68 % of the step) is crossed
  // within half the filter's support (3 s) of the step.
  EXPECT_NEAR(f.phases.steady.start, 10.0, 3.0);
  EXPECT_NEAR(f.phases.steady.end, 30.0, 3.0);
  EXPECT_NEAR(f.phases.steadyRateMedian, 0.3, 1e-6);
  EXPECT_TRUE(f.roseNote.empty()) << f.roseNote;
  EXPECT_DOUBLE_EQ(f.roseWindow.start, f.phases.steady.start);
  ASSERT_TRUE(f.rose.found) << f.rose.reason;
  EXPECT_EQ(f.rose.leaves, 9);
  EXPECT_GE(f.rose.span.start, f.phases.steady.start);
  EXPECT_LE(f.rose.span.end, f.phases.steady.end);
  ASSERT_TRUE(f.helix.loops.found) << f.helix.loops.reason;
  // Loops turn at the leaf rate w = 2.827 rad/s, but against a tangent that
  // turns at 0.04 rad/s, so they come (w - 0.04) / w times per leaf.
  EXPECT_NEAR(f.loopsPerLeaf, (2.827 - 0.04) / 2.827, 0.01);
}

TEST(TrialAnalyzer, WithoutPrecessionTheWholeTrialIsUsedAndSaidSo) {
  const TrialFeatures f = analyzeTrial(makeTrial(false).samples());
  EXPECT_FALSE(f.phases.found);
  EXPECT_NE(f.roseNote.find("whole trial"), std::string::npos);
  EXPECT_NE(f.helixNote.find("whole trial"), std::string::npos);
  ASSERT_TRUE(f.rose.found) << f.rose.reason;
  EXPECT_EQ(f.rose.leaves, 9);
  EXPECT_NEAR(f.roseWindow.duration(), 40.0, 1e-9);
}

// The rose and the helix of one window share one resampling (issue 32)
// only where each would have made the same series alone: their features
// must be those of the detectors run on their own columns, bit for bit;
// also where a NaN in one contact row makes the shared resampling drop a row
// that the rose keeps.
TEST(TrialAnalyzer, SharedResamplingGivesEachDetectorsOwnFeatures) {
  for (const bool withNan : {false, true}) {
    Trial trial = makeTrial(true);
    if (withNan) trial.contact.x[2000] = std::nan("");  // 20 s: inside the steady phase
    const TrialFeatures f = analyzeTrial(trial.samples());
    ASSERT_TRUE(f.phases.found) << f.phases.reason;
    std::size_t first = trial.mass.t.size(), last = 0;
    for (std::size_t i = 0; i < trial.mass.t.size(); ++i)
      if (trial.mass.t[i] >= f.phases.steady.start && trial.mass.t[i] <= f.phases.steady.end)
        first = std::min(first, i), last = i + 1;
    auto cut = [&](const std::vector<double>& c) { return std::span<const double>(c).subspan(first, last - first); };
    const RoseFeatures rose = detectRose(cut(trial.mass.t), cut(trial.mass.x), cut(trial.mass.y));
    const HelixFeatures helix = detectHelix(cut(trial.contact.t), cut(trial.contact.x), cut(trial.contact.y));
    ASSERT_TRUE(rose.found) << rose.reason;
    EXPECT_EQ(f.rose.leaves, rose.leaves);
    EXPECT_EQ(f.rose.centreX, rose.centreX);
    EXPECT_EQ(f.rose.centreY, rose.centreY);
    EXPECT_EQ(f.rose.leafPeriod.value, rose.leafPeriod.value);
    EXPECT_EQ(f.rose.tipX, rose.tipX);
    EXPECT_EQ(f.rose.span.start, rose.span.start);
    EXPECT_EQ(f.helix.arc.x, helix.arc.x);
    EXPECT_EQ(f.helix.arc.sweptAngle, helix.arc.sweptAngle);
    EXPECT_EQ(f.helix.loops.times, helix.loops.times);
    EXPECT_EQ(f.helix.loops.frequency, helix.loops.frequency);
  }
}

}  // namespace
}  // namespace hemiroll::analysis
