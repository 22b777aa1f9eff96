// Matching at equal cost and at equal error (tools/peers/PeerReport): the
// figures the targets are stated in.

#include "tools/peers/PeerReport.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hemiroll::tools::peers {
namespace {

// A first-order engine: error = 1e-3 (h / 1 ms), cost = 1e-2 (1 ms / h).
SceneStudy firstOrderStudy() {
  SceneStudy s;
  s.scene.horizon = 1.0;
  for (const double h : {2e-3, 1e-3, 5e-4, 2.5e-4}) {
    ScoredRun r;
    r.run.engine = "engine";
    r.run.setting = "tuned";
    r.run.step = h;
    r.score.contactError = 1e-3 * h / 1e-3;
    r.score.cpuPerSimSecond = 1e-2 * 1e-3 / h;
    s.runs.push_back(r);
  }
  ScoredRun failed;
  failed.run.engine = "engine";
  failed.run.setting = "tuned";
  failed.score.finite = false;
  s.runs.push_back(failed);
  return s;
}

TEST(PeerReportTest, CurvesLeaveFailedRunsOutAndRunByCost) {
  const SceneStudy s = firstOrderStudy();
  const std::vector<Curve> curves = curvesOf(s);
  ASSERT_EQ(curves.size(), 1u);
  ASSERT_EQ(curves[0].points.size(), 4u);
  for (std::size_t i = 1; i < 4; ++i)
    EXPECT_LT(curves[0].points[i - 1]->score.cpuPerSimSecond, curves[0].points[i]->score.cpuPerSimSecond);
}

TEST(PeerReportTest, MatchingIsExactOnAPowerLaw) {
  const SceneStudy s = firstOrderStudy();
  const Curve c = curvesOf(s)[0];
  // error * cost = 1e-5 along the curve.
  EXPECT_NEAR(errorAtCost(c, 3e-2), 1e-5 / 3e-2, 1e-15);
  EXPECT_NEAR(costAtError(c, 7e-4), 1e-5 / 7e-4, 1e-15);
  // Outside the measured range nothing is invented.
  EXPECT_TRUE(std::isnan(errorAtCost(c, 1e-3)));
  EXPECT_TRUE(std::isnan(costAtError(c, 1e-6)));
}

}  // namespace
}  // namespace hemiroll::tools::peers
