// game/research/sweep/SweepMaps: heatmaps of a finished sweep - the cells in the
// axes' order, tipped-over cells grey and marked, the aggregate over further
// axes named in the title; the sheets are well-formed SVG without NaN.

#include "game/research/sweep/SweepMaps.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "game/research/report/Heatmap.h"
#include "game/research/sweep/SweepError.h"
#include "game/research/sweep/SweepTable.h"
#include "tests/game/support/TinySweep.h"
#include "tests/support/TempDirectory.h"
#include "tests/support/XmlCheck.h"

namespace hemiroll::game {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;
using test::TempDirectory;

TEST(SweepMaps, TippedCellsAreGreyAndMarked) {
  const TempDirectory dir;
  test::runSweepInto(test::kTippingSweep, dir.path());
  const SweepData data = loadSweep(dir.path());
  const report::HeatmapDef map =
      sweepHeatmap(data, {task::SweepParam::k, task::SweepParam::Omega, findSweepMetric("steady_fraction"), {}});
  EXPECT_THAT(map.xCentres, ElementsAre(8.0, 16.0));
  EXPECT_THAT(map.yCentres, ElementsAre(-1.0, -0.3141592653589793));  // sorted increasing
  ASSERT_EQ(map.values.size(), 4u);
  // values[iy * nx + ix]: Omega = -1 (row 0) tipped for both k; Omega = -pi/10 did not.
  EXPECT_THAT(map.marks, ElementsAre("T", "T", "", ""));
  EXPECT_TRUE(std::isnan(map.values[0]));
  EXPECT_TRUE(std::isnan(map.values[1]));
  EXPECT_FALSE(std::isnan(map.values[2]));
  EXPECT_THAT(map.missingNote, HasSubstr("T: tipped over"));
  EXPECT_EQ(map.title, "steady share of the run");  // one point per cell: no aggregate to name
  const report::HeatmapDef stopped =
      sweepHeatmap(data, {task::SweepParam::k, task::SweepParam::Omega, findSweepMetric("stopped"), {}});
  EXPECT_THAT(stopped.values, ElementsAre(1.0, 1.0, 0.0, 0.0));  // the stopped runs count here

  const std::string svg = report::renderHeatmap(map);
  EXPECT_EQ(test::xmlProblem(svg), "");
  EXPECT_THAT(svg, Not(HasSubstr("nan")));
  EXPECT_EQ(test::occurrences(svg, ">T</text>"), 2u);
}

TEST(SweepMaps, FurtherAxesAreAggregatedAndSaidSo) {
  const TempDirectory dir;
  test::runSweepInto(R"(return { duration = 6, axes = {
      { param = "k", values = { 8, 10 } }, { param = "m_p", values = { 0.5, 1 } },
      { param = "Omega", values = { -0.6, -0.4 } } } })",
                     dir.path(), {}, 2);
  const SweepData data = loadSweep(dir.path());
  MapRequest request{task::SweepParam::Omega, task::SweepParam::k, findSweepMetric("max_tilt_rad"), Aggregate::Max};
  const report::HeatmapDef map = sweepHeatmap(data, request);
  EXPECT_EQ(map.title, "largest tilt, max over m_p (2 points/cell)");
  // The cell (Omega = -0.6, k = 8) holds points 0 (m_p 0.5) and 2 (m_p 1).
  const std::size_t tilt = sweepColumn("max_tilt_rad");
  EXPECT_EQ(map.values[0], std::max(std::stod(data.rows[0][tilt]), std::stod(data.rows[2][tilt])));
  EXPECT_EQ(sweepHeatmap(data, request, true).title, "largest tilt (max)");

  const auto sheets = sweepMapSheets(data);
  ASSERT_EQ(sheets.size(), 3u);  // k x m_p, k x Omega, m_p x Omega
  EXPECT_EQ(sheets[0].first, "map-k-m_p.svg");
  EXPECT_EQ(sheets[2].first, "map-m_p-Omega.svg");
  for (const auto& [name, svg] : sheets) {
    EXPECT_EQ(test::xmlProblem(svg), "") << name;
    EXPECT_THAT(svg, Not(HasSubstr("nan"))) << name;
    EXPECT_THAT(svg, HasSubstr("each cell aggregates 2 over")) << name;
  }
}

TEST(SweepMaps, RefusesWhatCannotBeMapped) {
  const TempDirectory dir;
  test::runSweepInto(test::kTippingSweep, dir.path() / "whole");
  const SweepData data = loadSweep(dir.path() / "whole");
  const SweepMetric* metric = findSweepMetric("loops");
  EXPECT_THROW(sweepHeatmap(data, {task::SweepParam::k, task::SweepParam::k, metric, {}}), SweepError);
  try {
    sweepHeatmap(data, {task::SweepParam::k, task::SweepParam::r1, metric, {}});
    FAIL();
  } catch (const SweepError& e) {
    EXPECT_THAT(e.what(), HasSubstr("r1 is not an axis of this sweep (its axes: k, Omega)"));
  }
  test::runSweepInto(test::kTippingSweep, dir.path() / "shard", {0, 2});
  try {
    loadSweep(dir.path() / "shard");
    FAIL();
  } catch (const SweepError& e) {
    EXPECT_THAT(e.what(), HasSubstr("holds no finished sweep"));
  }
}

}  // namespace
}  // namespace hemiroll::game
