// game/research/analysis TrialPlots: the trial's SVGs are well-formed, hold no NaN
// even when the data do, and show what was found.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "game/research/analysis/TrialPlots.h"
#include "game/research/report/LinePlot.h"
#include "tests/analysis/support/Synthetic.h"
#include "tests/support/XmlCheck.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

TEST(TrialPlots, OverviewOfARoseWithNaNSamples) {
  TrialData t;
  t.id = "gappy & rose";
  const test::Planar rose = test::rose(0.015, 0.008, 8, -M_PI / 10, 35.0, 100.0);
  const test::Planar trace = test::trochoidArc(0.05, 0.002, 0.002, 9 * M_PI / 10, 0.0, 35.0, 100.0);
  t.time = rose.t, t.massX = rose.x, t.massY = rose.y, t.contactX = trace.x, t.contactY = trace.y;
  for (double time : t.time) t.psi.push_back(-0.3 * time);
  for (std::size_t i = 1000; i < 1010; ++i) t.massX[i] = t.contactY[i] = t.psi[i] = std::numeric_limits<double>::quiet_NaN();
  const analysis::TrialFeatures f = analysis::analyzeTrial(t.samples());
  ASSERT_TRUE(f.rose.found) << f.rose.reason;
  const std::string svg = overviewSheet(t, f);
  EXPECT_EQ(test::xmlProblem(svg), "");
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_THAT(svg, HasSubstr("gappy &amp; rose"));
  EXPECT_THAT(svg, HasSubstr("rose: 9 leaves"));
  EXPECT_THAT(svg, HasSubstr(">steady precession</text>"));
  const std::string contact = report::renderLinePlot(contactTracePlot(t, f));
  EXPECT_THAT(contact, HasSubstr("loops</text>"));
  EXPECT_THAT(contact, HasSubstr("fitted arc, radius 5.0 cm"));
}

}  // namespace
}  // namespace hemiroll::game
