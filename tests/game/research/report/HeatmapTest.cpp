// game/research/report Heatmap: cells coloured by value, a colour bar with its label,
// grey cells for missing values, nothing broken for a bad grid.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "game/research/report/Heatmap.h"
#include "tests/support/XmlCheck.h"

namespace hemiroll::report {
namespace {

using ::testing::HasSubstr;

HeatmapDef sweep() {
  HeatmapDef def;
  def.title = "leaves per cycle";
  def.x.label = "k [-]";
  def.y.label = "Omega [rad/s]";
  def.xCentres = {7, 8, 9};
  def.yCentres = {-0.4, -0.3};
  def.values = {8, 9, 10, 8, std::numeric_limits<double>::quiet_NaN(), 10.5};
  def.colourBarLabel = "leaves";
  def.annotate = true;
  def.decimals = 1;
  def.missingNote = "tipped over";
  return def;
}

TEST(Heatmap, CellsColouredFromLowToHighWithAColourBar) {
  const std::string svg = renderHeatmap(sweep());
  EXPECT_EQ(test::xmlProblem(svg), "") << svg;
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  // Viridis ends: the lowest value (8, two cells) dark purple, the highest
  // (10.5, one cell) yellow; the colour bar's 64 steps sit half a step inside
  // the ends, so they add neither colour.
  EXPECT_EQ(test::occurrences(svg, "fill=\"#440154\""), 2u);
  EXPECT_EQ(test::occurrences(svg, "fill=\"#fde725\""), 1u);
  EXPECT_EQ(test::occurrences(svg, "fill=\"#dddddd\""), 2u);  // the missing cell and its key
  EXPECT_THAT(svg, HasSubstr(">tipped over</text>"));
  EXPECT_THAT(svg, HasSubstr(">leaves</text>"));
  EXPECT_THAT(svg, HasSubstr(">Omega [rad/s]</text>"));
  EXPECT_THAT(svg, HasSubstr(">10.5</text>"));  // annotation
}

// A sweep marks cells (T: the run tipped over) whatever their value; a
// mark takes an annotation's place.
TEST(Heatmap, MarksAreWrittenInTheirCells) {
  HeatmapDef def = sweep();
  def.marks = {"", "", "", "", "T", "t"};
  const std::string svg = renderHeatmap(def);
  EXPECT_EQ(test::xmlProblem(svg), "");
  EXPECT_EQ(test::occurrences(svg, ">T</text>"), 1u);
  EXPECT_EQ(test::occurrences(svg, ">t</text>"), 1u);
  // The colour bar's ticks say 9.0 and 10.5 too: count against the unmarked map.
  const std::string plain = renderHeatmap(sweep());
  EXPECT_EQ(test::occurrences(svg, ">10.5</text>"), test::occurrences(plain, ">10.5</text>") - 1);  // marked: no annotation
  EXPECT_EQ(test::occurrences(svg, ">9.0</text>"), test::occurrences(plain, ">9.0</text>"));
  def.marks.pop_back();  // not one per cell: ignored
  EXPECT_EQ(test::occurrences(renderHeatmap(def), ">T</text>"), 0u);
}

TEST(Heatmap, AGridThatDoesNotFitItsValuesIsSaidNotDrawn) {
  HeatmapDef def = sweep();
  def.values.pop_back();
  const std::string svg = renderHeatmap(def);
  EXPECT_EQ(test::xmlProblem(svg), "");
  EXPECT_THAT(svg, HasSubstr("no grid to show"));
}

}  // namespace
}  // namespace hemiroll::report
