#include "game/ui/scores/ScoreStore.h"

#include <gtest/gtest.h>

#include <sqlite3.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>

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

// Runs SQL on `file` through a connection of its own (another program's).
void execute(sqlite3* db, const char* sql) { ASSERT_EQ(sqlite3_exec(db, sql, nullptr, nullptr, nullptr), SQLITE_OK) << sql; }

bool movedAside(const std::filesystem::path& dir) {
  for (const auto& f : std::filesystem::directory_iterator(dir))
    if (f.path().filename().string().rfind("scores.sqlite.corrupt-", 0) == 0) return true;
  return false;
}

// Issue 33: a valid database another program holds (19 rows) was taken for
// corrupt and moved aside, and the game started empty. Busy is waited for;
// still held, the file is left alone and this session's scores stay in
// memory; once released, every row is there.
TEST(ScoreStoreTest, ALockedDatabaseIsWaitedForAndNeverMovedAside) {
  test::TempDirectory dir;
  const std::filesystem::path file = dir.path() / "scores.sqlite";
  {
    ScoreStore store(file);
    for (int i = 0; i < 19; ++i) ASSERT_TRUE(store.add(entry("ann", true, 10.0 + i, 50.0, "bronze")));
  }
  sqlite3* other = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &other), SQLITE_OK);
  execute(other, "BEGIN EXCLUSIVE; INSERT INTO trials(level, player, success, time, score, medal, at) "
                 "VALUES('Tilt', 'zed', 0, 1, NULL, 'none', 0);");
  {
    ScoreStore held(file);
    ASSERT_EQ(held.notes().size(), 1u);
    EXPECT_NE(held.notes()[0].find("is locked by another program"), std::string::npos) << held.notes()[0];
    EXPECT_NE(held.notes()[0].find("the file is left as it is"), std::string::npos);
    EXPECT_FALSE(movedAside(dir.path()));
    EXPECT_TRUE(held.add(entry("ann", true, 1.0, 99.0, "gold")));  // kept in memory
  }
  // Released within the wait: the store opens as usual.
  std::thread release([other] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    sqlite3_exec(other, "COMMIT;", nullptr, nullptr, nullptr);
  });
  // (Started after the thread: it meets the lock, waits, and gets in.)
  ScoreStore later(file);
  release.join();
  sqlite3_close(other);
  EXPECT_TRUE(later.notes().empty()) << later.notes().front();
  EXPECT_EQ(later.best("Tilt").attempts, 20);  // the 19, and the other program's row
  EXPECT_FALSE(movedAside(dir.path()));
}

// A row with NULL where the store wrote values (another program's table,
// without NOT NULL) ended every level start with "basic_string: construction
// from null is not valid". Every column is read null-safely.
TEST(ScoreStoreTest, NullColumnsAreReadAsNothing) {
  test::TempDirectory dir;
  const std::filesystem::path file = dir.path() / "scores.sqlite";
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  execute(db, "CREATE TABLE trials (id INTEGER PRIMARY KEY, level TEXT, player TEXT, success INTEGER, time REAL, "
              "score REAL, medal TEXT, at INTEGER);"
              "INSERT INTO trials(level, player, success, time, score, medal, at) VALUES('Tilt', 'ann', 1, 7.5, 80, NULL, 0);"
              "INSERT INTO trials(level, player, success, time, score, medal, at) VALUES('Tilt', NULL, NULL, NULL, NULL, NULL, NULL);");
  sqlite3_close(db);
  ScoreStore store(file);
  EXPECT_TRUE(store.notes().empty());
  const LevelBest best = store.best("Tilt");
  EXPECT_EQ(best.attempts, 2);
  ASSERT_TRUE(best.bestTime);
  EXPECT_EQ(*best.bestTime, 7.5);
  EXPECT_EQ(best.bestMedal, "none");
  EXPECT_EQ(store.personalBest("Tilt", "ann").attempts, 1);
}

// A database whose trials table is not the store's (a column missing) is
// not read as if it were: moved aside with the reason, a fresh one started.
TEST(ScoreStoreTest, AForeignSchemaIsMovedAsideNamingWhatIsMissing) {
  test::TempDirectory dir;
  const std::filesystem::path file = dir.path() / "scores.sqlite";
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  execute(db, "CREATE TABLE trials (id INTEGER PRIMARY KEY, level TEXT, player TEXT);");
  sqlite3_close(db);
  ScoreStore store(file);
  ASSERT_FALSE(store.notes().empty());
  EXPECT_NE(store.notes()[0].find("its trials table has no column 'success'"), std::string::npos) << store.notes()[0];
  EXPECT_TRUE(movedAside(dir.path()));
  EXPECT_TRUE(store.add(entry("ann", true, 3.0, std::nullopt, "none")));
}

// SQLite opens read-write, which a FIFO does not refuse; its first read then
// waited for ever. Anything but a regular file is left alone.
TEST(ScoreStoreTest, AFifoInTheDatabasesPlaceIsLeftAloneNotRead) {
  test::TempDirectory dir;
  const std::filesystem::path file = dir.path() / "scores.sqlite";
  ASSERT_EQ(mkfifo(file.c_str(), 0600), 0);
  ScoreStore store(file);
  ASSERT_EQ(store.notes().size(), 1u);
  EXPECT_NE(store.notes()[0].find("is not a regular file"), std::string::npos) << store.notes()[0];
  EXPECT_TRUE(std::filesystem::is_fifo(file));
  EXPECT_TRUE(store.add(entry("ann", true, 3.0, std::nullopt, "none")));  // in memory
}

}  // namespace
}  // namespace hemiroll::game
