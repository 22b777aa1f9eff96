#include "game/screens/LevelSelectScreen.h"

#include <gtest/gtest.h>

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
