// game/research/report SvgDocument: well-formed output, escaped text, no NaN ever.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "game/research/report/SvgDocument.h"
#include "tests/support/XmlCheck.h"

namespace hemiroll::report {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(SvgDocument, ElementsAreWellFormedAndTextEscaped) {
  SvgDocument doc(200, 100);
  Style frame;
  frame.stroke = "#444444";
  doc.rect({10, 10, 180, 80}, frame);
  doc.text({20, 30}, "a < b & \"c\" > 'd'", TextStyle{});
  doc.beginClip({10, 10, 180, 80});
  const std::vector<Point> points{{10, 10}, {50.125, 60}, {90, 10}};
  doc.polyline(points, frame);
  doc.endClip();
  const std::string svg = doc.str();
  EXPECT_EQ(test::xmlProblem(svg), "") << svg;
  EXPECT_THAT(svg, HasSubstr("a &lt; b &amp; &quot;c&quot; &gt; &apos;d&apos;"));
  EXPECT_THAT(svg, HasSubstr("points=\"10,10 50.13,60 90,10\""));  // two decimals, trailing zeros dropped
  EXPECT_THAT(svg, HasSubstr("viewBox=\"0 0 200 100\""));
}

TEST(SvgDocument, NonFiniteCoordinatesLeaveTheElementOut) {
  SvgDocument doc(100, 100);
  Style s;
  s.stroke = "black";
  doc.line({0, 0}, {kNaN, 5}, s);
  doc.circle({kNaN, 1}, 2, s);
  doc.rect({0, 0, std::numeric_limits<double>::infinity(), 3}, s);
  const std::vector<Point> bad{{0, 0}, {1, kNaN}};
  doc.polyline(bad, s);
  doc.text({kNaN, 0}, "x", TextStyle{});
  const std::string svg = doc.str();
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_THAT(svg, Not(HasSubstr("inf")));
  EXPECT_THAT(svg, Not(HasSubstr("<line")));
  EXPECT_THAT(svg, Not(HasSubstr("<circle")));
  EXPECT_THAT(svg, Not(HasSubstr("<polyline")));
  EXPECT_EQ(test::xmlProblem(svg), "");
}

TEST(SvgDocument, AClipLeftOpenIsClosedAndControlCharactersDropped) {
  SvgDocument doc(10, 10);
  doc.beginClip({0, 0, 10, 10});
  doc.text({1, 1}, std::string("bell\a"), TextStyle{});
  const std::string svg = doc.str();
  EXPECT_EQ(test::xmlProblem(svg), "") << svg;
  EXPECT_THAT(svg, HasSubstr(">bell</text>"));
}

}  // namespace
}  // namespace hemiroll::report
