// The window on a small machine (issue 27): frames paced to what the top
// screen needs (the frame cap in play, 30 fps watching the autopilot and in
// menus, 15 paused) so that
// the 1 kHz servo thread keeps a core; the shipped levels found from any
// folder (and, with none, a level select that says so and offers no Play);
// the results' one-key restart and next level; `hemiroll play --autoplay`
// reporting the loop's timing and stops. In a real window (Xvfb + llvmpipe).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>

#include "engine/platform/KeyNames.h"
#include "game/ui/app/App.h"
#include "game/ui/screens/LevelSelectScreen.h"
#include "game/ui/screens/PauseScreen.h"
#include "game/ui/screens/PlayScreen.h"
#include "game/ui/screens/ResultsScreen.h"
#include "game/ui/screens/ScreenStack.h"
#include "tests/game/ui/support/HiddenApp.h"
#include "tests/support/ProcessRunner.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// What each screen is paced to; and pacing holds the rate down: N frames
// of a menu take at least (N - 1) / 30 s, however fast llvmpipe draws them
// (a lower bound: no load can make the frames come sooner).
TEST(AppPacingTest, FramesArePacedToWhatTheTopScreenNeeds) {
  test::TempDirectory dir;
  {
    App unpaced(test::hiddenAppIn(dir.path()));  // the tests' own apps are not paced
    EXPECT_EQ(unpaced.targetFps(), 0.0);
  }
  AppDef def = test::hiddenAppIn(dir.path());
  def.paceFrames = true;
  App app(def);
  app.frame();
  EXPECT_EQ(app.targetFps(), App::kMenuFps);  // the title
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 16; ++i) app.frame();
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(took, 15.0 / App::kMenuFps * 0.98);  // 2 %: the sleep's rounding, never less
  EXPECT_GT(app.pacer().totalSleep(), 0.0);

  app.screens().push(std::make_unique<PlayScreen>(app, HEMIROLL_SOURCE_DIR "/levels/tutorial_01_tilt_and_return.lua"));
  app.frame();
  EXPECT_EQ(app.targetFps(), 60.0);  // the frame cap's default
  app.settings().frameCap = 40;
  EXPECT_EQ(app.targetFps(), 40.0);
  app.settings().frameCap = 1000;  // out of range: clamped to the largest allowed
  EXPECT_EQ(app.targetFps(), static_cast<double>(kFrameCapFps[1]));
  app.settings().frameCap = 60;
  // Watching the autopilot: nobody steers, its planner gets the CPU.
  auto* play = dynamic_cast<PlayScreen*>(app.screens().top());
  ASSERT_NE(play, nullptr);
  play->watchAutopilot();
  app.frame();
  EXPECT_EQ(app.targetFps(), App::kWatchFps);
  play->session()->takeOver();
  app.frame();
  EXPECT_EQ(app.targetFps(), 60.0);
  app.inject(platform::keyDownEvent("Escape"));
  app.frame();
  app.frame();
  EXPECT_STREQ(app.topScreen(), "pause");
  EXPECT_EQ(app.targetFps(), App::kStillFps);
}

// Started where no levels are: the level select says where it looked and
// offers nothing to play (no Play or Watch that cannot work).
TEST(AppPacingTest, NoLevelsFoundSaysSoAndOffersNoPlay) {
  test::TempDirectory dir;
  const fs::path before = fs::current_path();
  fs::current_path(dir.path());  // no ./levels; the test program has none beside it
  unsetenv("HEMIROLL_LEVELS");
  AppDef def = test::hiddenAppIn(dir.path());
  def.levelsDir = "";
  {
    App app(def);
    EXPECT_EQ(app.levelsDir(), "");
    app.screens().push(std::make_unique<LevelSelectScreen>(app));
    app.frame();
    auto* select = dynamic_cast<LevelSelectScreen*>(app.screens().top());
    ASSERT_NE(select, nullptr);
    EXPECT_TRUE(select->entries().empty());
    EXPECT_FALSE(select->playable());
    app.inject(platform::keyDownEvent("Return"));
    app.inject(platform::keyDownEvent("A"));
    app.frame();
    app.frame();
    EXPECT_STREQ(app.topScreen(), "levels");
  }
  fs::current_path(before);
}

// The results screen: R (or Enter) plays the level again, N the next one of
// the list the level select gave; the list's last level has no next.
TEST(AppPacingTest, TheResultsRestartWithOneKeyAndGoToTheNextLevel) {
  test::TempDirectory dir;
  App app(test::hiddenAppIn(dir.path()));
  const std::string first = HEMIROLL_SOURCE_DIR "/levels/tutorial_01_tilt_and_return.lua";
  const std::string second = HEMIROLL_SOURCE_DIR "/levels/tutorial_02_roll_a_short_distance.lua";
  TrialResult quit;
  quit.reason = "quit by the player";
  auto results = std::make_unique<ResultsScreen>(app, first, "01", quit);
  results->setPlaylist({first, second});
  EXPECT_EQ(results->nextLevel(), second);
  app.screens().push(std::move(results));
  app.frame();
  app.inject(platform::keyDownEvent("R"));
  app.frame();
  app.frame();
  auto* again = dynamic_cast<PlayScreen*>(app.screens().top());
  ASSERT_NE(again, nullptr) << app.topScreen();
  EXPECT_EQ(again->hud().title(), "01 Tilt and return");

  auto last = std::make_unique<ResultsScreen>(app, second, "02", quit);
  last->setPlaylist({first, second});
  EXPECT_EQ(last->nextLevel(), "");
  auto next = std::make_unique<ResultsScreen>(app, first, "01", quit);
  next->setPlaylist({first, second});
  app.screens().replace(std::move(next));
  app.frame();
  app.inject(platform::keyDownEvent("N"));
  app.frame();
  app.frame();
  auto* nextPlay = dynamic_cast<PlayScreen*>(app.screens().top());
  ASSERT_NE(nextPlay, nullptr) << app.topScreen();
  EXPECT_THAT(nextPlay->hud().title(), HasSubstr("02"));
}

// The real program from another folder: `hemiroll play levels/...` finds
// the shipped level there (as a checkout's README says to run it), plays it
// with the scripted mouse, and reports the loop's timing, the CPU it took
// and its stops (none: a mouse is not stopped by a late tick).
TEST(AppPacingTest, ThePlayCommandFindsTheLevelsFromAnotherFolderAndReports) {
  test::TempDirectory dir;
  const std::string d = dir.path().string();
  const test::ProcessResult r = test::runProcess(
      "/bin/sh", {"-c", "cd '" + d + "' && HEMIROLL_CONFIG_DIR='" + d + "' HEMIROLL_DATA_DIR='" + d + "' exec '" +
                            HEMIROLL_BINARY + "' play levels/tutorial_01_tilt_and_return.lua --autoplay 1.5"});
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("autoplay "));
  EXPECT_THAT(r.out, HasSubstr("frame cap 60 fps"));
  EXPECT_THAT(r.out, HasSubstr("servo loop: "));
  EXPECT_THAT(r.out, HasSubstr("safety stops: 0 (none)"));
  EXPECT_THAT(r.out, HasSubstr("trial: "));
}

}  // namespace
}  // namespace hemiroll::game
