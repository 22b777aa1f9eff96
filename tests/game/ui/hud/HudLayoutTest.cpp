// The play screen's layout in a real window (Xvfb + llvmpipe) at the sizes
// players use, 1280x720 and 1920x1080: every HUD window (the HUD, the
// level's messages, the take-hold prompt, the plots, the hint compass, the
// magnified floor) lies
// inside the window and none covers another, before taking hold and while
// playing with the hint and the full table on; and the results panel leaves
// the middle of the window, where the hemisphere stands, clear.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "engine/platform/KeyNames.h"
#include "game/ui/app/App.h"
#include "game/ui/screens/PlayScreen.h"
#include "game/ui/screens/ResultsScreen.h"
#include "tests/game/ui/support/HiddenApp.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using namespace std::chrono_literals;

struct WindowSize {
  int width, height;
};
void PrintTo(const WindowSize& s, std::ostream* out) { *out << s.width << "x" << s.height; }

std::string describe(const WindowRect& r) {
  return std::to_string(int(r.x)) + "," + std::to_string(int(r.y)) + " " + std::to_string(int(r.width)) + "x" +
         std::to_string(int(r.height));
}

class HudLayoutTest : public ::testing::TestWithParam<WindowSize> {
 protected:
  void SetUp() override {
    def_ = test::hiddenAppIn(dir_.path());
    def_.width = GetParam().width;
    def_.height = GetParam().height;
  }
  // Every rect inside the window, no two overlapping; `expected` are drawn.
  void checkLayout(const PlayHud& hud, std::initializer_list<const char*> expected) {
    const auto rects = hud.rects();
    const float w = static_cast<float>(GetParam().width), h = static_cast<float>(GetParam().height);
    for (const char* name : expected) {
      bool found = false;
      for (const WindowRect& r : rects) found = found || std::string(r.name) == name;
      EXPECT_TRUE(found) << name << " not drawn";
    }
    for (std::size_t i = 0; i < rects.size(); ++i) {
      const WindowRect& a = rects[i];
      EXPECT_TRUE(a.within(w, h)) << a.name << " at " << a.x << "," << a.y << " size " << a.width << "x" << a.height;
      EXPECT_GT(a.width * a.height, 0.0f) << a.name;
      for (std::size_t j = i + 1; j < rects.size(); ++j)
        EXPECT_FALSE(a.overlaps(rects[j])) << a.name << " covers " << rects[j].name << ": " << describe(a) << " and "
                                           << describe(rects[j]);
    }
  }
  test::TempDirectory dir_;
  AppDef def_;
};

TEST_P(HudLayoutTest, NothingClippedNothingOverlapping) {
  App app(def_);
  // Tutorial 3 has a message at the start, three plots and a two-component stage.
  app.screens().push(std::make_unique<PlayScreen>(app, HEMIROLL_SOURCE_DIR "/levels/tutorial_03_precess.lua"));
  app.frame();
  app.frame();  // auto-sized windows take their size in their second frame
  auto* play = dynamic_cast<PlayScreen*>(app.screens().top());
  ASSERT_NE(play, nullptr);
  ASSERT_NE(play->session(), nullptr) << play->error();
  EXPECT_THAT(play->hud().prompt(), ::testing::HasSubstr("to take hold"));
  checkLayout(play->hud(), {"hud", "messages", "prompt", "plots", "floor"});

  app.inject(platform::keyDownEvent("Space"));
  app.inject(platform::keyDownEvent("H"));
  app.inject(platform::keyDownEvent("I"));
  const auto start = std::chrono::steady_clock::now();
  while (!play->compass().shown() && std::chrono::steady_clock::now() - start < 5s) app.frame();
  ASSERT_TRUE(play->compass().shown()) << play->session()->autopilotNote();
  app.frame();
  EXPECT_TRUE(play->hud().fullTable());
  EXPECT_EQ(play->hud().prompt(), "");
  checkLayout(play->hud(), {"hud", "messages", "table", "hint", "floor"});  // the table in the plots' place
}

TEST_P(HudLayoutTest, TheResultsLeaveTheHemisphereInView) {
  App app(def_);
  app.screens().push(std::make_unique<PlayScreen>(app, HEMIROLL_SOURCE_DIR "/levels/tutorial_02_roll_a_short_distance.lua"));
  app.frame();
  app.inject(platform::keyDownEvent("Space"));
  for (int i = 0; i < 5; ++i) app.frame();
  auto* play = dynamic_cast<PlayScreen*>(app.screens().top());
  ASSERT_NE(play, nullptr);
  play->quit();  // the judge ends the trial; the results replace the play screen
  for (int i = 0; i < 3 && app.screens().top() == play; ++i) app.frame();
  auto* results = dynamic_cast<ResultsScreen*>(app.screens().top());
  ASSERT_NE(results, nullptr);
  EXPECT_TRUE(results->ending().hasScene);
  EXPECT_FALSE(results->ending().decidedBy.empty());
  app.frame();
  const WindowRect panel = results->panelRect();
  const float w = static_cast<float>(GetParam().width), h = static_cast<float>(GetParam().height);
  EXPECT_TRUE(panel.within(w, h));
  // The hemisphere is drawn about the window's middle, a fifth of its width across.
  const WindowRect middle{"hemisphere", w * 0.4f, h * 0.35f, w * 0.2f, h * 0.3f};
  EXPECT_FALSE(panel.overlaps(middle)) << "the panel starts at x = " << panel.x;
}

INSTANTIATE_TEST_SUITE_P(PlayersWindows, HudLayoutTest, ::testing::Values(WindowSize{1280, 720}, WindowSize{1920, 1080}),
                         [](const auto& info) {
                           return std::to_string(info.param.width) + "x" + std::to_string(info.param.height);
                         });

}  // namespace
}  // namespace hemiroll::game
