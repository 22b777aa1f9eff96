#pragma once
// The level select: every *.lua in the levels directory (sorted by file
// name), each loaded to show its name, difficulty and description, with the
// best time and medal from the scores database (or "tried N times" /
// "not played"). A level that does not load is listed as broken with its
// error (file:line: what), never hidden. No levels at all: it says where it
// looked and offers only Back.
// Keys: Up/Down (Home/End, Page Up/Down) choose, Enter plays, A watches the
// autopilot, Escape goes back. The keyboard's choice is the highlighted row
// (the pointer's hover only outlines one: Enter plays what is highlighted).

#include <optional>
#include <string>
#include <vector>

#include "engine/task/LevelDef.h"
#include "game/ui/scores/ScoreStore.h"
#include "game/ui/screens/ListingBudget.h"
#include "game/ui/screens/MedalTimes.h"
#include "game/ui/screens/Screen.h"

namespace hemiroll::game {

struct LevelEntry {
  std::string path;
  std::string name;         // the file name when broken
  std::string description;
  int difficulty = 0;
  std::string error;        // "" = loads
  // Not loaded: the listing's time ran out before this file (ListingBudget.h).
  // Shown with a note; choosing it loads it in full.
  bool pending = false;
  task::ScoringDef scoring;  // the medal thresholds the card shows
  std::optional<MedalTimes> medalTimes;  // the thresholds as times, where the score is a time
  LevelBest best;
};

// The levels in `dir` (not its subdirectories: levels/scenarios holds `sim`
// scenarios): the tutorials first (files named tutorial*, in name order),
// then the others from the lowest difficulty, then those the listing's time
// did not reach, broken files last. Each file is loaded within `budget`
// (ListingBudget.h), so no file, however hostile, holds the window long.
std::vector<LevelEntry> scanLevels(const std::string& dir, const ListingBudget& budget = {});
// The first level that loads and has not been won yet (0 when all have).
int firstToPlay(const std::vector<LevelEntry>& entries);
// What the list says of a level's record: "best 12.3 s, gold",
// "tried 3 times, not won yet", "not played".
std::string levelRecord(const LevelBest& best);

class LevelSelectScreen final : public Screen {
 public:
  using Screen::Screen;
  const char* name() const override { return "levels"; }
  void enter() override;
  void input(const platform::InputEvent& e) override;
  void paint() override;

  const std::vector<LevelEntry>& entries() const { return entries_; }
  int selected() const { return selected_; }
  // The selected level loads: Play and Watch are offered.
  bool playable() const;
  // The playable levels' files in the list's order (the results screen's "next level").
  std::vector<std::string> playlist() const;

 private:
  void play(bool watch = false);  // watch: the autopilot plays, the player may take over
  std::vector<LevelEntry> entries_;
  int selected_ = 0;
  bool entered_ = false;  // the first visit selects firstToPlay
};

}  // namespace hemiroll::game
