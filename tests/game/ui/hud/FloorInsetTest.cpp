// game/ui/hud/FloorInset's scale: round spans that fit the targets and nearby
// zones, changed with hysteresis so that the map does not breathe.
#include "game/ui/hud/FloorInset.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hemiroll::game {
namespace {

TEST(FloorInsetTest, TheSpanGrowsAtOnceAndShrinksOnlyWellInside) {
  // 4.7 mm needed: 5.9 mm with the margin fits the 10 mm span.
  EXPECT_EQ(FloorInset::kSpans[insetSpanIndex(0, 0.0047)], 0.01);
  // From 20 mm: 5.9 mm is under 80 % of 10 mm, so it shrinks to 10 mm.
  EXPECT_EQ(FloorInset::kSpans[insetSpanIndex(2, 0.0047)], 0.01);
  // 7.5 mm needed (9.4 mm with the margin) fits 10 mm but not well inside: 20 mm stays.
  EXPECT_EQ(FloorInset::kSpans[insetSpanIndex(2, 0.0075)], 0.02);
  // Growing is at once: 9 mm needed (11.25 mm) does not fit 10 mm.
  EXPECT_EQ(FloorInset::kSpans[insetSpanIndex(1, 0.009)], 0.02);
  EXPECT_EQ(insetSpanIndex(1, 10.0), FloorInset::kSpans.size() - 1);  // the largest at most
  EXPECT_EQ(insetSpanIndex(3, std::nan("")), 3u);
}

TEST(FloorInsetTest, TheForbiddenZonesPitAndTargetFitTheMap) {
  // The forbidden-zone challenge at its start: the target 3.5 mm along -x
  // (band 1.2 mm), the pit on the way: all within the 10 mm span.
  render::RenderScene s;
  s.centre = {0.0, 0.0, 0.04};
  s.targets.push_back({{-0.0035, 0.0}, {0.0012, 1e3}, false});  // y free
  s.forbidden.push_back({true, {-0.0018, 0.0}, 0.0012, {}, {}});
  FloorInset inset;
  inset.update(s, 0.0);
  EXPECT_EQ(inset.span(), 0.01);
  // A zone far away does not zoom the map out.
  s.forbidden.push_back({true, {0.3, 0.0}, 0.01, {}, {}});
  inset.update(s, 0.0);
  EXPECT_EQ(inset.span(), 0.01);
  // The paper's target, 5.7 cm off: the 10 cm span.
  s.targets = {{{-0.04, -0.04}, {0.004, 0.004}, false}};
  inset.update(s, 0.0);
  EXPECT_EQ(inset.span(), 0.1);
}

}  // namespace
}  // namespace hemiroll::game
