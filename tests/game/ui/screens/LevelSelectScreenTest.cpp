#include "game/ui/screens/LevelSelectScreen.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>

#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(LevelSelectScreenTest, ListsEveryLevelAndShowsABrokenOneWithItsError) {
  test::TempDirectory dir;
  dir.write("a_good.lua", readFile(HEMIROLL_SOURCE_DIR "/levels/tutorial_01_tilt_and_return.lua"));
  dir.write("b_broken.lua", "return { name = 'x', task = \n");  // a syntax error
  dir.write("notes.txt", "not a level");
  std::filesystem::create_directory(dir.path() / "scenarios");
  dir.write("scenarios/s.lua", "return {}");

  const std::vector<LevelEntry> entries = scanLevels(dir.path().string());
  ASSERT_EQ(entries.size(), 2u);  // *.lua only, subdirectories left out
  EXPECT_TRUE(entries[0].error.empty()) << entries[0].error;
  EXPECT_FALSE(entries[0].name.empty());
  EXPECT_NE(entries[0].name, "a_good.lua");  // the level's own name
  EXPECT_EQ(entries[1].name, "b_broken.lua");
  EXPECT_NE(entries[1].error.find("b_broken.lua"), std::string::npos) << entries[1].error;
}

// Listing loads every file on the window's thread (issue 33): a level whose
// top runs a C call for hours is refused at once; one that spends its whole
// wall clock (slow instructions: comparisons of 4 MB strings) is stopped at
// the listing's per-file limit; and once the listing's time is spent the
// files not reached are listed unloaded, to load when chosen.
TEST(LevelSelectScreenTest, HostileLevelsCannotHoldTheListing) {
  test::TempDirectory dir;
  dir.write("a_good.lua", readFile(HEMIROLL_SOURCE_DIR "/levels/tutorial_01_tilt_and_return.lua"));
  dir.write("b_escape.lua", "local s = string.rep('', math.maxinteger)\nreturn {}\n");
  const std::string slow =
      "local a = string.rep('a', 4e6) local b = a:sub(1, -2) .. 'b' local n = 0\n"
      "while true do if a < b then n = n + 1 end end\n";
  for (const char* name : {"c_slow.lua", "d_slow.lua", "e_slow.lua", "f_slow.lua"}) dir.write(name, slow);
  ListingBudget budget;
  budget.perFileSeconds = 0.1;
  budget.totalSeconds = 0.3;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<LevelEntry> entries = scanLevels(dir.path().string(), budget);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(entries.size(), 6u);
  EXPECT_TRUE(entries[0].error.empty()) << entries[0].error;  // the good level, loaded, first
  EXPECT_FALSE(entries[0].pending);
  int pending = 0, slowStopped = 0;
  bool escapeRefused = false;
  for (const LevelEntry& e : entries) {
    pending += e.pending;
    slowStopped += e.error.find("wall-clock limit of 0.1 s exceeded") != std::string::npos;
    escapeRefused |= e.error.find("b_escape.lua:1: string.rep: ") != std::string::npos;
  }
  EXPECT_TRUE(escapeRefused);
  // At least 0.1 s each: the listing's 0.3 s are spent by the third slow
  // file at the latest (sooner on a busy machine), and the rest wait.
  EXPECT_GE(slowStopped, 1);
  EXPECT_GE(pending, 1);
  EXPECT_EQ(slowStopped + pending, 4);
  EXPECT_LT(seconds, 2.0);
  // A file not reached is shown last but one (before the broken ones), can be chosen, and says why.
  const auto notReached = std::find_if(entries.begin(), entries.end(), [](const LevelEntry& e) { return e.pending; });
  ASSERT_NE(notReached, entries.end());
  EXPECT_EQ(notReached - entries.begin(), 1);  // after the loaded one, before the broken
  EXPECT_NE(notReached->description.find("not loaded: the list took its 0.3 s"), std::string::npos);
  EXPECT_EQ(firstToPlay(entries), 0);
}

TEST(LevelSelectScreenTest, AMissingDirectoryIsAnEmptyList) {
  EXPECT_TRUE(scanLevels("/no/such/levels/dir").empty());
}

// A new player meets the tutorials first, in order; then the rest from the easiest.
TEST(LevelSelectScreenTest, TheTutorialsComeFirstThenTheEasiest) {
  const std::vector<LevelEntry> entries = scanLevels(HEMIROLL_SOURCE_DIR "/levels");
  ASSERT_GE(entries.size(), 6u);
  const auto tutorial = [&](std::size_t i) {
    return std::filesystem::path(entries[i].path).filename().string().rfind("tutorial_", 0) == 0;
  };
  std::size_t tutorials = 0;
  while (tutorials < entries.size() && tutorial(tutorials)) ++tutorials;
  EXPECT_GE(tutorials, 5u);  // 01 to 05, the helix
  for (std::size_t i = 0; i < tutorials; ++i)
    EXPECT_EQ(std::filesystem::path(entries[i].path).filename().string().substr(0, 12),
              "tutorial_0" + std::to_string(i + 1) + "_")
        << entries[i].path;
  for (std::size_t i = tutorials; i < entries.size(); ++i) {
    EXPECT_FALSE(tutorial(i)) << entries[i].path << ": a tutorial after the others";
    if (i > tutorials) {
      EXPECT_LE(entries[i - 1].difficulty, entries[i].difficulty);
    }
  }
}

TEST(LevelSelectScreenTest, TheFirstLevelNotYetWonIsSelected) {
  std::vector<LevelEntry> entries(4);
  entries[0].best.bestTime = 12.0;        // won
  entries[1].error = "x.lua:1: broken";   // cannot be played
  EXPECT_EQ(firstToPlay(entries), 2);
  entries[2].best.bestTime = 3.0;
  entries[3].best.bestTime = 4.0;
  EXPECT_EQ(firstToPlay(entries), 0);     // all won: the top
  EXPECT_EQ(firstToPlay({}), 0);
}

TEST(LevelSelectScreenTest, TheShippedLevelsAllLoad) {
  for (const LevelEntry& e : scanLevels(HEMIROLL_SOURCE_DIR "/levels")) EXPECT_TRUE(e.error.empty()) << e.error;
}

}  // namespace
}  // namespace hemiroll::game
