// The play keys in a real window (Xvfb + llvmpipe): a key changed on the
// settings screen is the key the play screen answers to, the old one no
// longer is, and the HUD's hint names the new one; taking hold by click or
// by key after any pointer motion.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "engine/physics/StateKinematics.h"
#include "engine/platform/KeyNames.h"
#include "game/ui/app/App.h"
#include "game/ui/screens/PlayScreen.h"
#include "game/ui/screens/SettingsScreen.h"
#include "tests/game/ui/support/HiddenApp.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

// Frames until the servo loop's snapshot shows `wanted`, for up to 2 s (the
// command takes a tick or two; the margin is for a loaded machine).
bool frameUntil(App& app, PlayScreen& play, haptics::Engagement wanted) {
  for (int i = 0; i < 200; ++i) {
    app.frame();
    if (play.session()->snapshot().engagement == wanted) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST(PlayKeysTest, AKeyChangedInTheSettingsIsTheOneThatPlays) {
  test::TempDirectory dir;
  App app(test::hiddenAppIn(dir.path()));

  // Settings: take hold -> H; then Escape while choosing a key cancels, not leaves.
  app.screens().push(std::make_unique<SettingsScreen>(app));
  app.frame();
  auto* settings = dynamic_cast<SettingsScreen*>(app.screens().top());
  ASSERT_NE(settings, nullptr);
  settings->listenFor(KeyAction::TakeHold);
  app.frame();
  app.inject(platform::keyDownEvent("H"));
  app.frame();
  EXPECT_FALSE(settings->listening().has_value());
  EXPECT_EQ(app.settings().keys.keyName(KeyAction::TakeHold), "H");
  settings->listenFor(KeyAction::LetGo);
  app.inject(platform::keyDownEvent("Escape"));
  app.frame();
  app.frame();  // screen changes asked for in a frame apply at the start of the next
  ASSERT_EQ(app.screens().top(), settings) << "Escape while choosing a key left the screen";
  EXPECT_EQ(app.settings().keys.keyName(KeyAction::LetGo), "Backspace");
  app.inject(platform::keyDownEvent("Escape"));
  app.frame();
  app.frame();
  EXPECT_NE(app.screens().top(), settings);

  app.screens().push(std::make_unique<PlayScreen>(app, HEMIROLL_SOURCE_DIR "/levels/tutorial_01_tilt_and_return.lua"));
  app.frame();
  auto* play = dynamic_cast<PlayScreen*>(app.screens().top());
  ASSERT_NE(play, nullptr);
  ASSERT_NE(play->session(), nullptr) << play->error();
  EXPECT_EQ(play->hud().takeHoldHint(), "click or H to take hold");

  // Space is free now: it does nothing. H takes hold (the proxy starts on the mass point).
  // (A taking hold shows within a tick or two, as Armed or ramping in.)
  app.inject(platform::keyDownEvent("Space"));
  for (int i = 0; i < 20; ++i) {
    app.frame();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(play->session()->snapshot().engagement, haptics::Engagement::Disengaged);
  app.inject(platform::keyDownEvent("H"));
  EXPECT_TRUE(frameUntil(app, *play, haptics::Engagement::Engaged));
  // Backspace lets go (the ramp out ends disengaged).
  app.inject(platform::keyDownEvent("Backspace"));
  EXPECT_TRUE(frameUntil(app, *play, haptics::Engagement::Disengaged));
}

}  // namespace
}  // namespace hemiroll::game

namespace hemiroll::game {
namespace {

// Taking hold in the window is one action that always works: after any
// pointer motion (here 6 cm off and up the wheel), a click or Space puts
// the proxy on the mass point, engages it and starts the clock; before it
// the clock stands at zero and the screen says what to do; after letting go
// it says how to carry on.
class TakeHoldTest : public ::testing::TestWithParam<bool> {};

TEST_P(TakeHoldTest, AClickOrSpaceAfterAnyPointerMotionTakesHoldAndStartsTheClock) {
  const bool useSpace = GetParam();
  test::TempDirectory dir;
  App app(test::hiddenAppIn(dir.path()));
  app.screens().push(std::make_unique<PlayScreen>(app, HEMIROLL_SOURCE_DIR "/levels/tutorial_02_roll_a_short_distance.lua"));
  app.frame();
  auto* play = dynamic_cast<PlayScreen*>(app.screens().top());
  ASSERT_NE(play, nullptr);
  ASSERT_NE(play->session(), nullptr) << play->error();

  platform::InputEvent stroke;
  stroke.type = platform::InputType::PointerMove;
  stroke.dx = 80.0;
  stroke.dy = -60.0;
  for (int i = 0; i < 3; ++i) app.inject(stroke);  // 240 x 180 px: 6 cm right, 4.5 cm up at 0.25 mm/px
  platform::InputEvent wheel;
  wheel.type = platform::InputType::Wheel;
  wheel.wheel = 4.0;
  app.inject(wheel);
  for (int i = 0; i < 10; ++i) {
    app.frame();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(play->session()->snapshot().time, 0.0);  // the clock waits
  EXPECT_NE(play->hud().prompt().find("to take hold"), std::string::npos) << play->hud().prompt();
  const physics::Vec3 massPoint =
      physics::massPointPosition(physics::forceStateOf(play->session()->snapshot().state), 0.04);  // R of tutorial 2
  EXPECT_GT((play->session()->pointerScene() - massPoint).norm(), 0.05);  // the pointer wandered off

  if (useSpace) {
    app.inject(platform::keyDownEvent("Space"));
  } else {
    platform::InputEvent click;
    click.type = platform::InputType::ButtonDown;
    click.button = platform::PointerButton::Left;
    app.inject(click);
  }
  ASSERT_TRUE(frameUntil(app, *play, haptics::Engagement::Engaged));
  EXPECT_GT(play->session()->snapshot().time, 0.0);
  EXPECT_LT(play->session()->snapshot().proxyDistance, 0.002);  // on the mass point, not where the pointer was
  EXPECT_EQ(play->hud().prompt(), "");

  app.inject(platform::keyDownEvent("Backspace"));
  ASSERT_TRUE(frameUntil(app, *play, haptics::Engagement::Disengaged));
  app.frame();
  EXPECT_NE(play->hud().prompt().find("take hold again"), std::string::npos) << play->hud().prompt();
  app.inject(platform::keyDownEvent("Space"));
  EXPECT_TRUE(frameUntil(app, *play, haptics::Engagement::Engaged));
}

INSTANTIATE_TEST_SUITE_P(ClickAndSpace, TakeHoldTest, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Space" : "Click"; });

}  // namespace
}  // namespace hemiroll::game
