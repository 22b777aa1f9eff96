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

TEST(LevelSelectScreenTest, TheShippedLevelsAllLoad) {
  for (const LevelEntry& e : scanLevels(HEMIROLL_SOURCE_DIR "/levels")) EXPECT_TRUE(e.error.empty()) << e.error;
}

}  // namespace
}  // namespace hemiroll::game
