#pragma once
// Highscores and personal bests in a small SQLite database, scores.sqlite
// in the data directory (record::dataDirectory).
// One row per finished trial (level, player, outcome, time, score, medal,
// when); bests are queries over them. A corrupt database, a file that is not
// one, or one whose trials table lacks a column the store uses, is moved
// aside (scores.sqlite.corrupt-<unix time>) with a note, and a fresh one is
// started. A database another program holds (busy, locked) is waited for
// (kBusyWaitMs) and, still held, never moved: the store works in memory for
// this session and says so; so it does when nothing else works. Every
// column is read null-safely (a file may hold NULL anywhere). Never throws
// after construction, never crashes the game.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

struct sqlite3;

namespace hemiroll::game {

struct ScoreEntry {
  std::string level;      // the level's name
  std::string player = "player";
  bool success = false;
  double time = 0.0;      // [s] simulated trial time
  std::optional<double> score;
  std::string medal = "none";
  std::int64_t when = 0;  // unix time [s]
};

struct LevelBest {
  std::optional<double> bestTime;   // fastest success [s]
  std::optional<double> bestScore;
  std::string bestMedal = "none";   // the best medal won
  int attempts = 0;
};

class ScoreStore {
 public:
  // Opens (creating) `file`; "" = record::dataDirectory()/scores.sqlite.
  explicit ScoreStore(std::filesystem::path file = {});
  ~ScoreStore();
  ScoreStore(const ScoreStore&) = delete;
  ScoreStore& operator=(const ScoreStore&) = delete;

  // Adds a trial; returns false (with note()) when it could not be stored.
  bool add(const ScoreEntry& entry);
  LevelBest best(const std::string& level) const;
  LevelBest personalBest(const std::string& level, const std::string& player) const;
  // How long a busy database is waited for, at opening and at each statement.
  static constexpr int kBusyWaitMs = 2000;
  // Notes from opening (a database moved aside, in-memory fallback).
  const std::vector<std::string>& notes() const { return notes_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  enum class Opened { Ok, Busy, Unusable, Failed };
  Opened open(const std::filesystem::path& file);
  // "" when the trials table has every column the store uses, with its type.
  std::string schemaProblem() const;
  LevelBest query(const std::string& level, const std::string* player) const;

  std::filesystem::path file_;
  sqlite3* db_ = nullptr;
  std::vector<std::string> notes_;
  std::string openError_;  // why the last open failed
};

}  // namespace hemiroll::game
