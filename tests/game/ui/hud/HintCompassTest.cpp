// game/ui/hud/HintCompass: the hint's move in screen directions is the inverse
// of how the mouse's strokes move the proxy (PointerMapping), whatever the
// camera's heading: following the compass's arrow with the mouse moves the
// proxy where the autopilot wants it.
#include "game/ui/hud/HintCompass.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/haptics/PointerMapping.h"

namespace hemiroll::game {
namespace {

TEST(HintCompassTest, TheArrowIsTheStrokeThatMakesTheMove) {
  for (const double heading : {0.0, 0.7, 1.5707963267948966, 2.5, -2.0}) {
    for (const auto& [dxPx, dyPx] : {std::pair{10.0, 0.0}, {0.0, -10.0}, {3.0, 4.0}, {-7.0, 2.0}}) {
      haptics::PointerMapping mapping;
      mapping.setScreenYaw(heading);
      const haptics::Vec3 before = mapping.position();
      mapping.moveBy(dxPx, dyPx);
      const haptics::Vec3 move = mapping.position() - before;
      double right = 0.0, up = 0.0;
      toScreenDirections(move.x(), move.y(), heading, right, up);
      const double metresPerPixel = mapping.def().metresPerPixel;
      // Screen y grows downwards: a stroke up the screen (dy < 0) is "up".
      EXPECT_NEAR(right, dxPx * metresPerPixel, 1e-15) << heading;
      EXPECT_NEAR(up, -dyPx * metresPerPixel, 1e-15) << heading;
    }
  }
}

TEST(HintCompassTest, NonFiniteMovesAreNotShown) {
  HintCompass compass;
  compass.show(0.002, -0.001);
  EXPECT_TRUE(compass.shown());
  compass.show(std::nan(""), 0.0);
  EXPECT_FALSE(compass.shown());
  compass.show(0.001, 0.0);
  compass.hide();
  EXPECT_FALSE(compass.shown());
}

}  // namespace
}  // namespace hemiroll::game
