// game/research/report LinePlot: lines break at NaN, equal axes, bands, legend.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <regex>
#include <string>

#include "game/research/report/LinePlot.h"
#include "tests/support/XmlCheck.h"

namespace hemiroll::report {
namespace {

using ::testing::HasSubstr;

TEST(LinePlot, ALineBreaksAtNaNAndNeverWritesIt) {
  LinePlotDef def;
  def.title = "psi";
  def.x.label = "t [s]";
  def.y.label = "psi [rad]";
  Series s;
  s.label = "psi";
  for (int i = 0; i < 100; ++i) {
    s.x.push_back(0.1 * i);
    s.y.push_back(i == 50 ? std::numeric_limits<double>::quiet_NaN() : std::sin(0.1 * i));
  }
  def.series.push_back(s);
  def.bands.push_back({2.0, 4.0, "steady", "#2ca02c", 0.15});
  const std::string svg = renderLinePlot(def);
  EXPECT_EQ(test::xmlProblem(svg), "") << svg;
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(test::occurrences(svg, "<polyline"), 2u);  // before and after the NaN
  EXPECT_THAT(svg, HasSubstr(">steady</text>"));
  EXPECT_THAT(svg, HasSubstr(">t [s]</text>"));
  EXPECT_THAT(svg, HasSubstr(">psi</text>"));  // title and legend
}

TEST(LinePlot, EqualAspectGivesAUnitTheSameLengthOnBothAxes) {
  // A circle of radius 1 cm must come out round: its polyline's extent in x and y must match.
  LinePlotDef def;
  def.x = {"u_a [cm]", 100.0};
  def.y = {"v_a [cm]", 100.0};
  def.equalAspect = true;
  Series circle;
  for (int i = 0; i <= 360; ++i) {
    circle.x.push_back(0.05 + 0.01 * std::cos(i * M_PI / 180));
    circle.y.push_back(0.01 * std::sin(i * M_PI / 180));
  }
  def.series.push_back(circle);
  const std::string svg = renderLinePlot(def, 800, 400);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, std::regex("points=\"([^\"]*)\"")));
  const std::string points = m[1];
  double xMin = 1e9, xMax = -1e9, yMin = 1e9, yMax = -1e9;
  const std::regex pair("(-?[0-9.]+),(-?[0-9.]+)");
  for (auto it = std::sregex_iterator(points.begin(), points.end(), pair); it != std::sregex_iterator(); ++it) {
    const double x = std::stod((*it)[1]), y = std::stod((*it)[2]);
    xMin = std::min(xMin, x), xMax = std::max(xMax, x), yMin = std::min(yMin, y), yMax = std::max(yMax, y);
  }
  // Pixels are rounded to 0.01 and points within a pixel of the last one skipped: equal within 2 px.
  EXPECT_NEAR(xMax - xMin, yMax - yMin, 2.0);
  EXPECT_GT(xMax - xMin, 50.0);
}

TEST(LinePlot, EmptyPlotStillDrawsItsAxes) {
  LinePlotDef def;
  def.title = "nothing";
  const std::string svg = renderLinePlot(def);
  EXPECT_EQ(test::xmlProblem(svg), "");
  EXPECT_THAT(svg, HasSubstr(">nothing</text>"));
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

}  // namespace
}  // namespace hemiroll::report
