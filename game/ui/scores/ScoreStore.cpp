#include "game/ui/scores/ScoreStore.h"

#include <sqlite3.h>

#include <algorithm>
#include <cmath>
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
  // SQLite opens read-write, which a FIFO does not refuse; its first read
  // would then wait for ever. Anything but a regular file is left alone.
  if (std::filesystem::exists(file_, ec) && !std::filesystem::is_regular_file(file_, ec)) {
    notes_.push_back("the scores database " + file_.string() +
                     " is not a regular file; this session's scores are kept in memory only and it is left as it is");
    open(":memory:");
    return;
  }
  const Opened opened = open(file_);
  if (opened == Opened::Ok) return;
  if (opened == Opened::Busy) {
    // Another program holds it (a second game, an editor, a backup): it is
    // not ours to move. Waited for; still held, this game's scores live in
    // memory and the file is left as it is.
    notes_.push_back("the scores database " + file_.string() + " is locked by another program (waited " +
                     std::to_string(kBusyWaitMs / 1000.0).substr(0, 3) +
                     " s); this session's scores are kept in memory only and the file is left as it is");
  } else if (opened == Opened::Unusable) {
    // Corrupt, not a database, or not our table: kept for the player to
    // inspect, and a fresh one started.
    const std::filesystem::path aside = file_.string() + ".corrupt-" + std::to_string(std::time(nullptr));
    std::filesystem::rename(file_, aside, ec);
    if (!ec) {
      notes_.push_back("the scores database " + file_.string() + " was unreadable (" + openError_ +
                       "); moved aside to " + aside.string() + " and started a new one");
      if (open(file_) == Opened::Ok) return;
    }
    notes_.push_back("scores are kept in memory only this time: " + file_.string() + " cannot be opened");
  } else {
    notes_.push_back("scores are kept in memory only this time: " + file_.string() + " cannot be opened (" +
                     openError_ + ")");
  }
  open(":memory:");
}

ScoreStore::~ScoreStore() {
  if (db_) sqlite3_close(db_);
}

namespace {

// What a failed step says about the file: busy (another connection holds
// it), unusable (corrupt, not a database), or another error (permissions,
// I/O) that moving the file would not mend.
bool isBusy(int code) { return (code & 0xff) == SQLITE_BUSY || (code & 0xff) == SQLITE_LOCKED; }
bool isCorrupt(int code) { return (code & 0xff) == SQLITE_CORRUPT || (code & 0xff) == SQLITE_NOTADB; }

// The columns the store reads and writes, each with the type it stores.
constexpr const char* kColumns[][2] = {{"id", "INTEGER"}, {"level", "TEXT"},  {"player", "TEXT"},
                                       {"success", "INTEGER"}, {"time", "REAL"}, {"score", "REAL"},
                                       {"medal", "TEXT"},  {"at", "INTEGER"}};

}  // namespace

ScoreStore::Opened ScoreStore::open(const std::filesystem::path& file) {
  if (db_) {
    sqlite3_close(db_);
    db_ = nullptr;
  }
  openError_.clear();
  const auto fail = [this](Opened kind, int code) {
    openError_ = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(code);
    sqlite3_close(db_);
    db_ = nullptr;
    return kind;
  };
  int code = sqlite3_open(file.c_str(), &db_);
  if (code != SQLITE_OK) return fail(isCorrupt(code) ? Opened::Unusable : Opened::Failed, code);
  // Busy: SQLite retries for this long before a statement gives up.
  sqlite3_busy_timeout(db_, kBusyWaitMs);
  // A quick check reads every page: a damaged file fails here, not mid-game.
  std::string result;
  code = sqlite3_exec(
      db_, "PRAGMA quick_check;",
      [](void* out, int, char** values, char**) {
        if (values[0] != nullptr) *static_cast<std::string*>(out) += values[0];
        return 0;
      },
      &result, nullptr);
  if (isBusy(code)) return fail(Opened::Busy, code);
  if (code != SQLITE_OK) return fail(isCorrupt(code) ? Opened::Unusable : Opened::Failed, code);
  if (result != "ok") {
    openError_ = "quick_check: " + result.substr(0, 200);
    sqlite3_close(db_);
    db_ = nullptr;
    return Opened::Unusable;
  }
  code = sqlite3_exec(db_, kSchema, nullptr, nullptr, nullptr);
  if (isBusy(code)) return fail(Opened::Busy, code);
  if (code != SQLITE_OK) return fail(isCorrupt(code) ? Opened::Unusable : Opened::Failed, code);
  // The table may be another program's (or an older one's): every column the
  // store uses must be there with its type.
  if (const std::string problem = schemaProblem(); !problem.empty()) {
    openError_ = problem;
    sqlite3_close(db_);
    db_ = nullptr;
    return Opened::Unusable;
  }
  return Opened::Ok;
}

std::string ScoreStore::schemaProblem() const {
  sqlite3_stmt* st = nullptr;
  if (sqlite3_prepare_v2(db_, "SELECT name, type FROM pragma_table_info('trials')", -1, &st, nullptr) != SQLITE_OK)
    return "its trials table cannot be read";
  std::vector<std::pair<std::string, std::string>> columns;
  while (sqlite3_step(st) == SQLITE_ROW) {
    const auto* name = sqlite3_column_text(st, 0);
    const auto* type = sqlite3_column_text(st, 1);
    columns.emplace_back(name ? reinterpret_cast<const char*>(name) : "", type ? reinterpret_cast<const char*>(type) : "");
  }
  sqlite3_finalize(st);
  for (const auto& column : kColumns) {
    const char* name = column[0];
    const char* type = column[1];
    // (clang 14 captures no structured binding: plain names.)
    const auto found = std::find_if(columns.begin(), columns.end(), [name](const auto& c) { return c.first == name; });
    if (found == columns.end()) return std::string("its trials table has no column '") + name + "'";
    if (found->second != type)
      return std::string("its trials table's column '") + name + "' is " + (found->second.empty() ? "untyped" : found->second) +
             ", not " + type;
  }
  return "";
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
    const bool success = sqlite3_column_type(st, 0) != SQLITE_NULL && sqlite3_column_int(st, 0) != 0;
    const bool timed = sqlite3_column_type(st, 1) != SQLITE_NULL;
    const double time = sqlite3_column_double(st, 1);
    if (success && timed && std::isfinite(time) && time >= 0.0 && (!b.bestTime || time < *b.bestTime))
      b.bestTime = time;
    if (sqlite3_column_type(st, 2) != SQLITE_NULL) {
      const double score = sqlite3_column_double(st, 2);
      if (std::isfinite(score) && (!b.bestScore || score > *b.bestScore)) b.bestScore = score;
    }
    // Every column read null-safely: a row may hold NULL or a value of
    // another type whatever the schema says (SQLite's columns take any).
    const unsigned char* medalText = sqlite3_column_text(st, 3);
    const std::string medal = medalText != nullptr ? reinterpret_cast<const char*>(medalText) : "none";
    if (medalRank(medal) > medalRank(b.bestMedal)) b.bestMedal = medal;
  }
  sqlite3_finalize(st);
  return b;
}

}  // namespace hemiroll::game
