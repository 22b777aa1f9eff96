// game/ui/view/ShippedDirectories: the game finds its levels from any folder,
// as it finds its assets (issue 27: started elsewhere it found assets/ but
// not levels/, and still offered Play).
#include "game/ui/view/ShippedDirectories.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "game/ui/scores/ScoreStore.h"
#include "game/ui/screens/LevelSelectScreen.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

namespace fs = std::filesystem;

// Restores the working directory (the finder looks at ./levels first).
struct InDirectory {
  explicit InDirectory(const fs::path& dir) : before(fs::current_path()) { fs::current_path(dir); }
  ~InDirectory() { fs::current_path(before); }
  fs::path before;
};

// An installed tree: <root>/bin/hemiroll and <root>/levels/*.lua, the game
// started from an unrelated folder.
TEST(ShippedDirectoriesTest, LevelsAreFoundBesideTheProgramFromAnotherFolder) {
  test::TempDirectory root;
  fs::create_directories(root.path() / "bin");
  fs::create_directories(root.path() / "elsewhere" / "levels");
  fs::create_directories(root.path() / "levels");
  root.write("levels/a.lua", "return { name = 'a' }");
  const fs::path program = root.path() / "bin" / "hemiroll";
  unsetenv("HEMIROLL_LEVELS");
  InDirectory cd(root.path() / "elsewhere");
  EXPECT_EQ(fs::path(findLevelsDirectory(program)), root.path() / "levels");
  // A level named as in a checkout (levels/a.lua) is found there too.
  EXPECT_EQ(fs::path(resolveLevelPath("levels/a.lua", findLevelsDirectory(program))),
            root.path() / "levels" / "a.lua");
  // A file that is where it says is taken as given; a missing one stays as
  // given, for the loader to name.
  root.write("elsewhere/mine.lua", "return { name = 'mine' }");
  EXPECT_EQ(resolveLevelPath("mine.lua", findLevelsDirectory(program)), "mine.lua");
  EXPECT_EQ(resolveLevelPath("levels/none.lua", findLevelsDirectory(program)), "levels/none.lua");
  // The folder the game starts in comes first: a player's own levels (an
  // empty ./levels, as above, was passed over).
  root.write("elsewhere/levels/own.lua", "return { name = 'own' }");
  EXPECT_EQ(findLevelsDirectory(program), "levels");
  // HEMIROLL_LEVELS before all.
  setenv("HEMIROLL_LEVELS", (root.path() / "levels").c_str(), 1);
  EXPECT_EQ(fs::path(findLevelsDirectory(program)), root.path() / "levels");
  unsetenv("HEMIROLL_LEVELS");
}

// Nowhere: "" (the level select then says where it looked, and offers no Play).
TEST(ShippedDirectoriesTest, NoLevelsAnywhereIsAnEmptyAnswer) {
  test::TempDirectory root;
  fs::create_directories(root.path() / "bin");
  unsetenv("HEMIROLL_LEVELS");
  InDirectory cd(root.path());
  EXPECT_EQ(findLevelsDirectory(root.path() / "bin" / "hemiroll"), "");
  const std::vector<fs::path> looked = levelsDirectoryCandidates(root.path() / "bin" / "hemiroll");
  ASSERT_EQ(looked.size(), 3u);
  EXPECT_EQ(looked[0], "levels");
}

// What the level list says of a record: failed and quit attempts are
// attempts, not "not played".
TEST(ShippedDirectoriesTest, TheLevelListSaysWhatWasPlayed) {
  LevelBest none;
  EXPECT_EQ(levelRecord(none), "not played");
  LevelBest tried;
  tried.attempts = 3;
  EXPECT_EQ(levelRecord(tried), "tried 3 times, not won yet");
  tried.attempts = 1;
  EXPECT_EQ(levelRecord(tried), "tried 1 time, not won yet");
  LevelBest won;
  won.attempts = 2;
  won.bestTime = 12.34;
  won.bestMedal = "gold";
  EXPECT_EQ(levelRecord(won), "best 12.3 s, gold");
  won.bestMedal = "none";
  EXPECT_EQ(levelRecord(won), "best 12.3 s");
}

}  // namespace
}  // namespace hemiroll::game
