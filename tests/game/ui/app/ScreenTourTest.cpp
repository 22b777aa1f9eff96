#include "game/ui/app/ScreenTour.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/platform/KeyNames.h"
#include "game/ui/app/App.h"
#include "game/ui/screens/LevelSelectScreen.h"
#include "game/ui/screens/PlayScreen.h"
#include "game/ui/screens/ReplayScreen.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Pixels within `tolerance` per channel of an RGB colour. The tolerance
// covers text anti-aliasing: only the glyphs' solid cores match.
int countColour(const render::Image& image, int r, int g, int b, int tolerance = 12, int x0 = 0, int y0 = 0,
                int x1 = -1, int y1 = -1) {
  if (x1 < 0) x1 = image.width;
  if (y1 < 0) y1 = image.height;
  int n = 0;
  for (int y = std::max(0, y0); y < std::min(y1, image.height); ++y)
    for (int x = std::max(0, x0); x < std::min(x1, image.width); ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      n += std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance && std::abs(p[2] - b) <= tolerance;
    }
  return n;
}

// title -> settings -> title -> level select -> play (a scripted mouse takes hold) -> pause ->
// results, driven by the same InputEvents a player makes, in a real window
// under Xvfb with llvmpipe.
TEST(ScreenTourTest, TitleLevelsPlayPauseResultsWithSyntheticInput) {
  test::TempDirectory dir;
  std::filesystem::create_directory(dir.path() / "levels");
  const std::string good = dir.write("levels/a_tilt.lua",
                                     readFile(HEMIROLL_SOURCE_DIR "/levels/tutorial_01_tilt_and_return.lua"));
  dir.write("levels/b_broken.lua", "return { name = \n");
  // A level whose top would run one C call for hours (issue 33): the level
  // select must still come up, listing it as broken.
  dir.write("levels/c_escape.lua", "local s = string.rep('', math.maxinteger)\nreturn {}\n");
  AppDef def;
  def.hidden = true;
  def.vsync = false;
  def.levelsDir = (dir.path() / "levels").string();
  def.scoresFile = (dir.path() / "scores.sqlite").string();
  def.settingsFile = (dir.path() / "settings.json").string();  // not the user's
  setenv("HEMIROLL_DATA_DIR", dir.path().c_str(), 1);  // replays go here
  App app(def);
  ScreenTourDef tour;
  tour.level = good;
  tour.playSeconds = 1.5;
  tour.autopilot = false;  // its stops: the next test
  const std::vector<ScreenTourStop> stops = runScreenTour(app, tour);

  ASSERT_EQ(stops.size(), 7u);
  const char* expected[] = {"title", "settings", "levels", "play", "pause", "results", "replay"};
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(stops[i].screen, expected[i]);
    EXPECT_EQ(stops[i].image.width, 1280);
    EXPECT_EQ(stops[i].image.height, 720);
  }
  // The title's name in gold (0.95, 0.8, 0.35): its glyph cores are ~160
  // pixels with ImGui's built-in font at 3x; half of that leaves room for
  // rasteriser differences, and the other screens have none.
  EXPECT_GT(countColour(stops[0].image, 242, 204, 89), 80);
  EXPECT_EQ(countColour(stops[2].image, 242, 204, 89), 0);
  // The settings' section headings are gold too (Device, Force method, Keys, ...).
  EXPECT_GT(countColour(stops[1].image, 242, 204, 89), 80);
  // The broken level is listed, its error in red (1, 0.5, 0.4); the title has none.
  EXPECT_GT(countColour(stops[2].image, 255, 128, 102), 100);
  EXPECT_EQ(countColour(stops[0].image, 255, 128, 102), 0);
  // The play screen draws the scene: the menus' plain background (0.09, 0.1,
  // 0.13) is gone from the middle of the window.
  const std::uint8_t* centre = stops[3].image.pixel(640, 360);
  EXPECT_FALSE(std::abs(centre[0] - 23) < 4 && std::abs(centre[1] - 26) < 4 && std::abs(centre[2] - 33) < 4);
  EXPECT_GT(countColour(stops[0].image, 23, 26, 33, 2), 1280 * 720 / 2);
  EXPECT_LT(countColour(stops[3].image, 23, 26, 33, 2), 1280 * 720 / 50);
  // The HUD's tolerance lines are drawn: green "in", red "out", amber for
  // the count while some are out (the compact HUD lists only those).
  EXPECT_GT(countColour(stops[3].image, 89, 217, 102) + countColour(stops[3].image, 242, 102, 89) +
                countColour(stops[3].image, 242, 191, 77),
            50);
  // The trial quit from the pause screen was stored as one attempt, not completed.
  const std::vector<LevelEntry> levels = scanLevels(def.levelsDir);
  ASSERT_EQ(levels.size(), 3u);
  EXPECT_NE(levels.back().error.find("string.rep: "), std::string::npos) << levels.back().error;
  const LevelBest best = app.scores().best(levels.front().name);
  EXPECT_EQ(best.attempts, 1);
  EXPECT_FALSE(best.bestTime);

  // Results: keep the replay (S), then watch it (W) through ReplayDevice.
  app.inject(platform::keyDownEvent("S"));
  app.frame();
  int saved = 0;
  for (const auto& f : std::filesystem::directory_iterator(dir.path() / "replays"))
    saved += f.path().extension() == ".hrr" && f.path().filename() != "last-trial.hrr";
  EXPECT_EQ(saved, 1);
  app.inject(platform::keyDownEvent("W"));
  for (int i = 0; i < 10; ++i) app.frame();
  EXPECT_STREQ(app.topScreen(), "replay");
  auto* replay = dynamic_cast<ReplayScreen*>(app.screens().top());
  ASSERT_NE(replay, nullptr);
  EXPECT_EQ(replay->error(), "");
  EXPECT_GT(replay->ticksPlayed(), 0u);
  EXPECT_GT(replay->ticksTotal(), 1000u);  // the 1.5 s played
}

// The tour's autopilot stops: watched from the level select (the HUD's green
// "AUTOPILOT playing" line), then taken over with the hint on (its line).
TEST(ScreenTourTest, TheAutopilotIsWatchedThenTakenOverWithTheHint) {
  test::TempDirectory dir;
  AppDef def;
  def.hidden = true;
  def.vsync = false;
  def.levelsDir = HEMIROLL_SOURCE_DIR "/levels";
  def.scoresFile = (dir.path() / "scores.sqlite").string();
  def.settingsFile = (dir.path() / "settings.json").string();
  setenv("HEMIROLL_DATA_DIR", dir.path().c_str(), 1);
  App app(def);
  ScreenTourDef tour;
  tour.level = HEMIROLL_SOURCE_DIR "/levels/tutorial_04_stop_on_target.lua";
  tour.playSeconds = 1.0;
  const std::vector<ScreenTourStop> stops = runScreenTour(app, tour);
  EXPECT_EQ(stops[7].screen, "watch");
  EXPECT_EQ(stops[8].screen, "hint");
  ASSERT_EQ(stops.size(), 11u);
  EXPECT_EQ(stops[9].screen, "start");
  EXPECT_EQ(stops[10].screen, "letgo");
  // The take-hold-again prompt is drawn where the HUD placed it, in amber (0.95,
  // 0.75, 0.3), at 1.3x: two lines have some 200 solid glyph-core pixels.
  // Counted inside its window only: the HUD's own amber lines are elsewhere.
  auto* start = dynamic_cast<PlayScreen*>(app.screens().top());
  ASSERT_NE(start, nullptr);
  const WindowRect* prompt = nullptr;
  for (const WindowRect& r : start->hud().rects())
    if (std::string(r.name) == "prompt") prompt = &r;
  ASSERT_NE(prompt, nullptr) << "no take-hold prompt drawn";
  EXPECT_GT(countColour(stops[10].image, 242, 191, 77, 12, int(prompt->x), int(prompt->y),
                        int(prompt->x + prompt->width), int(prompt->y + prompt->height)),
            100);
  // The autopilot's HUD line is green (0.3, 0.95, 0.55): one line of ImGui's
  // built-in font at 1x has about 80 solid glyph-core pixels of it (measured:
  // 80 for the hint's line), half that leaves room for the rasteriser; the
  // mouse's play has none.
  EXPECT_GT(countColour(stops[7].image, 77, 242, 140), 40);
  EXPECT_GT(countColour(stops[8].image, 77, 242, 140), 40);
  EXPECT_EQ(countColour(stops[3].image, 77, 242, 140), 0);
  // The last stops are a fresh trial of the player's own (the takeover
  // itself: AutopilotWatchTest), its clock waiting for the take-hold, then
  // taken hold of and let go: the physics stands still until the next take-hold.
  EXPECT_FALSE(start->session()->assisted());
  EXPECT_EQ(start->session()->frozen(), Freeze::LetGo);
  EXPECT_THAT(start->hud().prompt(), ::testing::HasSubstr("take hold again"));
}

}  // namespace
}  // namespace hemiroll::game
