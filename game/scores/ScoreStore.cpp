#include "game/scores/ScoreStore.h"

#include <sqlite3.h>

#include <cstdlib>
#include <ctime>
#include <system_error>
#include "engine/record/DataDirectory.h"

namespace hemiroll::game {

namespace {

constexpr const char* kSchema =
    "CREATE TABLE IF NOT EXISTS trials ("
    " id INTEGER PRIMARY KEY, level TEXT NOT NULL, player TEXT NOT NULL, success INTEGER NOT NULL,"
    " time REAL NOT NULL, score REAL, medal TEXT NOT NULL, at INTEGER NOT NULL);"
    "CREATE INDEX IF NOT EXISTS trials_level ON trials(level);";

int medalRank(const std::string& m) {
  if (m == "gold") return 3;
  if (m == "silver") return 2;
  if (m == "bronze") return 1;
  return 0;
}

}  // namespace

ScoreStore::ScoreStore(std::filesystem::path file) : file_(file.empty() ? record::dataDirectory() / "scores.sqlite" : file) {
  std::error_code ec;
  std::filesystem::create_directories(file_.parent_path(), ec);
  if (open(file_)) return;
  // Corrupt or not a database: keep it for the player to inspect, start afresh.
  const std::filesystem::path aside = file_.string() + ".corrupt-" + std::to_string(std::time(nullptr));
  std::filesystem::rename(file_, aside, ec);
  if (!ec) {
    notes_.push_back("the scores database " + file_.string() + " was unreadable; moved aside to " + aside.string() +
                     " and started a new one");
    if (open(file_)) return;
  }
  notes_.push_back("scores are kept in memory only this time: " + file_.string() + " cannot be opened");
  open(":memory:");
}

ScoreStore::~ScoreStore() {
  if (db_) sqlite3_close(db_);
}

bool ScoreStore::open(const std::filesystem::path& file) {
  if (db_) {
    sqlite3_close(db_);
    db_ = nullptr;
  }
  if (sqlite3_open(file.c_str(), &db_) != SQLITE_OK) {
    sqlite3_close(db_);
    db_ = nullptr;
    return false;
  }
  sqlite3_busy_timeout(db_, 200);
  // A quick check reads every page: a damaged file fails here, not mid-game.
  char* error = nullptr;
  bool ok = sqlite3_exec(db_, "PRAGMA quick_check;", nullptr, nullptr, &error) == SQLITE_OK;
  sqlite3_free(error);
  error = nullptr;
  ok = ok && sqlite3_exec(db_, kSchema, nullptr, nullptr, &error) == SQLITE_OK;
  sqlite3_free(error);
  if (!ok) {
    sqlite3_close(db_);
    db_ = nullptr;
  }
  return ok;
}

bool ScoreStore::add(const ScoreEntry& e) {
  if (!db_) return false;
  sqlite3_stmt* st = nullptr;
  if (sqlite3_prepare_v2(db_, "INSERT INTO trials(level, player, success, time, score, medal, at) VALUES(?,?,?,?,?,?,?)",
                         -1, &st, nullptr) != SQLITE_OK)
    return false;
  sqlite3_bind_text(st, 1, e.level.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(st, 2, e.player.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_int(st, 3, e.success ? 1 : 0);
  sqlite3_bind_double(st, 4, e.time);
  if (e.score)
    sqlite3_bind_double(st, 5, *e.score);
  else
    sqlite3_bind_null(st, 5);
  sqlite3_bind_text(st, 6, e.medal.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_int64(st, 7, e.when != 0 ? e.when : static_cast<std::int64_t>(std::time(nullptr)));
  const bool ok = sqlite3_step(st) == SQLITE_DONE;
  sqlite3_finalize(st);
  if (!ok) notes_.push_back(std::string("a score could not be stored: ") + sqlite3_errmsg(db_));
  return ok;
}

LevelBest ScoreStore::best(const std::string& level) const { return query(level, nullptr); }

LevelBest ScoreStore::personalBest(const std::string& level, const std::string& player) const {
  return query(level, &player);
}

LevelBest ScoreStore::query(const std::string& level, const std::string* player) const {
  LevelBest b;
  if (!db_) return b;
  const char* sql = player ? "SELECT success, time, score, medal FROM trials WHERE level = ? AND player = ?"
                           : "SELECT success, time, score, medal FROM trials WHERE level = ?";
  sqlite3_stmt* st = nullptr;
  if (sqlite3_prepare_v2(db_, sql, -1, &st, nullptr) != SQLITE_OK) return b;
  sqlite3_bind_text(st, 1, level.c_str(), -1, SQLITE_TRANSIENT);
  if (player) sqlite3_bind_text(st, 2, player->c_str(), -1, SQLITE_TRANSIENT);
  while (sqlite3_step(st) == SQLITE_ROW) {
    ++b.attempts;
    const bool success = sqlite3_column_int(st, 0) != 0;
    const double time = sqlite3_column_double(st, 1);
    if (success && (!b.bestTime || time < *b.bestTime)) b.bestTime = time;
    if (sqlite3_column_type(st, 2) != SQLITE_NULL) {
      const double score = sqlite3_column_double(st, 2);
      if (!b.bestScore || score > *b.bestScore) b.bestScore = score;
    }
    const std::string medal = reinterpret_cast<const char*>(sqlite3_column_text(st, 3));
    if (medalRank(medal) > medalRank(b.bestMedal)) b.bestMedal = medal;
  }
  sqlite3_finalize(st);
  return b;
}

}  // namespace hemiroll::game
