// game/research/report PlotSheet: panels in a grid on one page.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "game/research/report/PlotSheet.h"
#include "tests/support/XmlCheck.h"

namespace hemiroll::report {
namespace {

using ::testing::HasSubstr;

TEST(PlotSheet, ThreePanelsInTwoColumnsMakeTwoRows) {
  PlotSheet sheet(2, 400, 300, "trial 1");
  for (const char* title : {"one", "two"}) {
    LinePlotDef plot;
    plot.title = title;
    plot.series.push_back({"", {0, 1, 2}, {1, 0, 1}});
    sheet.add(plot);
  }
  HeatmapDef map;
  map.title = "three";
  map.xCentres = {1, 2};
  map.yCentres = {1};
  map.values = {0.5, 0.7};
  sheet.add(map);
  const std::string svg = sheet.svg();
  EXPECT_EQ(test::xmlProblem(svg), "") << svg;
  EXPECT_THAT(svg, HasSubstr("viewBox=\"0 0 800 636\""));  // 36 px title + 2 x 300
  for (const char* title : {">one<", ">two<", ">three<", ">trial 1<"}) EXPECT_THAT(svg, HasSubstr(title));
}

}  // namespace
}  // namespace hemiroll::report
