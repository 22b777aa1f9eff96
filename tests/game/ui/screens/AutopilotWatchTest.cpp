// The autopilot in the real window (Xvfb + llvmpipe): watched, it holds the
// proxy and plays in real time beside the servo loop (on its own thread);
// the player takes over with a click and the proxy stays where it was; the
// hint shows the autopilot's plan and moves nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <thread>

#include "engine/platform/KeyNames.h"
#include "game/ui/app/App.h"
#include "game/ui/screens/FreePlay.h"
#include "game/ui/screens/PlayScreen.h"
#include "tests/game/ui/support/HiddenApp.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

const std::string kLevels = HEMIROLL_SOURCE_DIR "/levels/";

class AutopilotWatchTest : public ::testing::Test {
 protected:
  void SetUp() override { def_ = test::hiddenAppIn(dir_.path()); }
  PlayScreen* watch(App& app, const std::string& level) {
    app.screens().push(std::make_unique<PlayScreen>(app, std::make_unique<FreePlay>(app, kLevels + level, true)));
    app.frame();
    return dynamic_cast<PlayScreen*>(app.screens().top());
  }
  test::TempDirectory dir_;
  AppDef def_;
};

// Watched, the autopilot holds the proxy and plays in real time: engaged at
// once, planning all along, the proxy moving, the servo loop untroubled. (It
// wins tutorial 02 at 6.5 s in most real-time runs, not all: real-time play
// is not deterministic, and the autopilot sometimes fails to settle there,
// in the window as with `run --realtime`; so winning is measured, not
// asserted. An assisted run's results: GhostRaceTest.)
TEST_F(AutopilotWatchTest, WatchedTheAutopilotHoldsTheProxyAndPlans) {
  App app(def_);
  PlayScreen* play = watch(app, "tutorial_02_roll_a_short_distance.lua");
  ASSERT_NE(play, nullptr);
  ASSERT_NE(play->session(), nullptr) << play->error();
  EXPECT_TRUE(play->session()->assisted());
  bool sawTheLine = false, engaged = false;
  double minX = 1.0, maxX = -1.0;
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < 3s && app.screens().top() == play) {
    app.frame();
    // A display's pace (about 120 Hz): unthrottled llvmpipe frames would take
    // a whole core of this 2-core machine from the autopilot's planner.
    std::this_thread::sleep_for(8ms);
    const haptics::ServoSnapshot& s = play->session()->snapshot();
    engaged = engaged || s.engagement == haptics::Engagement::Engaged;
    minX = std::min(minX, s.proxyPosition[0]);
    maxX = std::max(maxX, s.proxyPosition[0]);
    sawTheLine = sawTheLine || play->hud().autopilot().find("AUTOPILOT playing") != std::string::npos;
  }
  ASSERT_EQ(app.screens().top(), play);  // 3 s: it has not won yet (6.5 s)
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(play->session()->autopilotHolds());
  EXPECT_TRUE(engaged);
  EXPECT_TRUE(sawTheLine);
  EXPECT_EQ(play->session()->autopilotNote(), "");
  EXPECT_EQ(play->session()->fault(), haptics::SafetyFault::None);
  // Planned all along: 500 Hz nominal; a fifth of it leaves room for a loaded machine.
  EXPECT_GT(static_cast<double>(play->session()->autopilotPlans()), 100.0 * seconds);
  // It rolls the hemisphere 4 mm along x: the proxy travels.
  EXPECT_GT(maxX - minX, 0.002);
}

TEST_F(AutopilotWatchTest, AClickTakesOverWhereTheAutopilotLeftTheProxy) {
  App app(def_);
  PlayScreen* play = watch(app, "paper_reaching.lua");
  ASSERT_NE(play, nullptr);
  ASSERT_NE(play->session(), nullptr) << play->error();
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < 1500ms) app.frame();
  ASSERT_TRUE(play->session()->autopilotHolds());
  EXPECT_EQ(play->session()->snapshot().engagement, haptics::Engagement::Engaged);
  platform::InputEvent click;
  click.type = platform::InputType::ButtonDown;
  click.button = platform::PointerButton::Left;
  app.inject(click);
  app.frame();
  EXPECT_FALSE(play->session()->autopilotHolds());
  // The mouse now holds the proxy, from where the autopilot left it: after
  // a few frames the loop's proxy is the pointer's, and still engaged.
  for (int i = 0; i < 20; ++i) app.frame();
  const haptics::Triple& proxy = play->session()->snapshot().proxyPosition;
  const haptics::Vec3 pointer = play->session()->pointerScene();
  EXPECT_LT((haptics::Vec3(proxy[0], proxy[1], proxy[2]) - pointer).norm(), 1e-9);
  EXPECT_EQ(play->session()->snapshot().engagement, haptics::Engagement::Engaged);
  EXPECT_EQ(play->session()->fault(), haptics::SafetyFault::None);
}

TEST_F(AutopilotWatchTest, TheHintShowsThePlanAndMovesNothing) {
  App app(def_);
  app.screens().push(std::make_unique<PlayScreen>(app, kLevels + "tutorial_04_stop_on_target.lua"));
  app.frame();
  auto* play = dynamic_cast<PlayScreen*>(app.screens().top());
  ASSERT_NE(play, nullptr);
  ASSERT_NE(play->session(), nullptr) << play->error();
  EXPECT_FALSE(play->session()->assisted());
  // The autopilot plans from the running trial: it runs from the take-hold.
  app.inject(platform::keyDownEvent("Space"));
  app.inject(platform::keyDownEvent("H"));
  haptics::GuideSample plan;
  bool planned = false;
  const auto start = std::chrono::steady_clock::now();
  while (!planned && std::chrono::steady_clock::now() - start < 5s) {
    app.frame();
    planned = play->session()->hint(plan);
  }
  ASSERT_TRUE(planned) << play->session()->autopilotNote();
  EXPECT_THAT(play->hud().autopilot(), HasSubstr("circle round the green ring"));
  app.frame();
  EXPECT_TRUE(play->compass().shown());
  // At a person's bandwidth (issue 26): once the autopilot stirs, the hint
  // is its ring with a pace, not a point 0.3 s ahead; the same cue the
  // human model follows (HintSmoother), a few millimetres across.
  HintRing ring;
  bool stirring = false;
  const auto ringStart = std::chrono::steady_clock::now();
  while (!stirring && std::chrono::steady_clock::now() - ringStart < 5s) {
    app.frame();
    stirring = play->session()->hintRing(ring) && ring.kind == HintRing::Stir && play->compass().stirring();
  }
  ASSERT_TRUE(stirring);
  EXPECT_GT(ring.radius, 0.0);
  EXPECT_LT(ring.radius, 0.01);
  EXPECT_NE(ring.rate, 0.0);
  // The player holds the proxy and makes no strokes: it stays put however
  // the plan moves.
  const haptics::Vec3 before = play->session()->pointerScene();
  for (int i = 0; i < 30; ++i) app.frame();
  EXPECT_EQ(play->session()->pointerScene(), before);
  EXPECT_FALSE(play->session()->assisted());
  app.inject(platform::keyDownEvent("H"));  // off again
  app.frame();
  EXPECT_EQ(play->hud().autopilot(), "");
  EXPECT_FALSE(play->compass().shown());
}

}  // namespace
}  // namespace hemiroll::game
