#include "game/scores/ScoreStore.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

ScoreEntry entry(const std::string& player, bool success, double time, std::optional<double> score,
                 const std::string& medal) {
  ScoreEntry e;
  e.level = "Tilt";
  e.player = player;
  e.success = success;
  e.time = time;
  e.score = score;
  e.medal = medal;
  return e;
}

TEST(ScoreStoreTest, BestTimeScoreAndMedalPerLevelAndPlayer) {
  test::TempDirectory dir;
  ScoreStore store(dir.path() / "scores.sqlite");
  EXPECT_TRUE(store.notes().empty());
  ASSERT_TRUE(store.add(entry("ann", true, 20.0, 70.0, "silver")));
  ASSERT_TRUE(store.add(entry("ann", false, 5.0, std::nullopt, "none")));  // a failure is never the best time
  ASSERT_TRUE(store.add(entry("bob", true, 12.5, 90.0, "gold")));
  const LevelBest all = store.best("Tilt");
  EXPECT_EQ(all.attempts, 3);
  ASSERT_TRUE(all.bestTime);
  EXPECT_EQ(*all.bestTime, 12.5);
  EXPECT_EQ(*all.bestScore, 90.0);
  EXPECT_EQ(all.bestMedal, "gold");
  const LevelBest ann = store.personalBest("Tilt", "ann");
  EXPECT_EQ(ann.attempts, 2);
  EXPECT_EQ(*ann.bestTime, 20.0);
  EXPECT_EQ(ann.bestMedal, "silver");
  EXPECT_EQ(store.best("Other").attempts, 0);
  EXPECT_FALSE(store.best("Other").bestTime);
}

TEST(ScoreStoreTest, ScoresSurviveReopening) {
  test::TempDirectory dir;
  {
    ScoreStore store(dir.path() / "scores.sqlite");
    ASSERT_TRUE(store.add(entry("ann", true, 9.0, 50.0, "bronze")));
  }
  ScoreStore again(dir.path() / "scores.sqlite");
  EXPECT_EQ(*again.best("Tilt").bestTime, 9.0);
}

TEST(ScoreStoreTest, ACorruptDatabaseIsMovedAsideWithANoteAndAFreshOneWorks) {
  test::TempDirectory dir;
  const std::string file = dir.write("scores.sqlite", std::string(4096, 'x'));
  ScoreStore store(file);
  ASSERT_FALSE(store.notes().empty());
  EXPECT_NE(store.notes().front().find("moved aside"), std::string::npos) << store.notes().front();
  bool aside = false;
  for (const auto& f : std::filesystem::directory_iterator(dir.path()))
    if (f.path().filename().string().rfind("scores.sqlite.corrupt-", 0) == 0) aside = true;
  EXPECT_TRUE(aside);
  EXPECT_TRUE(store.add(entry("ann", true, 3.0, std::nullopt, "none")));
  EXPECT_EQ(store.best("Tilt").attempts, 1);
}

}  // namespace
}  // namespace hemiroll::game
