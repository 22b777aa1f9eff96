#include "game/ui/hud/ImGuiLayer.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "game/ui/app/App.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

bool near(const std::uint8_t* p, int r, int g, int b) {
  return std::abs(p[0] - r) <= 6 && std::abs(p[1] - g) <= 6 && std::abs(p[2] - b) <= 6;
}

// A click whose press and release arrive in the same frame (what a
// synthetic or a fast real click does) still presses an ImGui button: the
// title's first button, found by its colour, opens the level select.
TEST(ImGuiLayerTest, APressAndReleaseInOneFrameClickAButton) {
  test::TempDirectory dir;
  AppDef def;
  def.hidden = true;
  def.vsync = false;
  def.scoresFile = (dir.path() / "s.sqlite").string();
  def.settingsFile = (dir.path() / "settings.json").string();  // not the user's
  def.levelsDir = HEMIROLL_SOURCE_DIR "/levels";
  App app(def);
  app.inject(platform::leftPointerEvent(platform::InputType::PointerMove, 5, 5));  // away from every button
  app.frame();
  app.requestCapture();
  app.frame();
  const render::Image& title = app.capture();
  // ImGui's button colour (0.26, 0.59, 0.98) at 40% over the panel: (35, 70, 110).
  int buttonY = -1;
  for (int y = 0; y < title.height && buttonY < 0; ++y)
    if (near(title.pixel(title.width / 2, y), 35, 70, 110)) buttonY = y;
  ASSERT_GE(buttonY, 0) << "no button on the title screen";
  EXPECT_STREQ(app.topScreen(), "title");
  const double x = title.width / 2.0, y = buttonY + 8.0;
  app.inject(platform::leftPointerEvent(platform::InputType::PointerMove, x, y));
  app.frame();  // hovered first, as a real pointer would be
  app.inject(platform::leftPointerEvent(platform::InputType::ButtonDown, x, y));
  app.inject(platform::leftPointerEvent(platform::InputType::ButtonUp, x, y));
  for (int i = 0; i < 4; ++i) app.frame();
  EXPECT_STREQ(app.topScreen(), "levels");
}

}  // namespace
}  // namespace hemiroll::game
