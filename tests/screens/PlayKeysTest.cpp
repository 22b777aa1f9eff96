// The play keys in a real window (Xvfb + llvmpipe): a key changed on the
// settings screen is the key the play screen answers to, the old one no
// longer is, and the HUD's hint names the new one.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "engine/platform/KeyNames.h"
#include "game/app/App.h"
#include "game/screens/PlayScreen.h"
#include "game/screens/SettingsScreen.h"
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
  AppDef def;
  def.hidden = true;
  def.vsync = false;
  def.scoresFile = (dir.path() / "scores.sqlite").string();
  def.settingsFile = (dir.path() / "settings.json").string();
  App app(def);

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
