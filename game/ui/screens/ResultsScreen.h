#pragma once
// The end of a trial: outcome and reason, time and what decided it (and
// what the servo loop's timing did: stops, stalls ridden out), score, medal
// and the level's medal thresholds (as times where the score is a time), the
// personal best before this trial, and whether it is a new one; drawn beside
// the trial's last frame (its final pose and contact trace), keeping the
// hemisphere in view, with confetti for a success. The trial is stored in
// the scores database when the screen is made. The trial's replay log can be
// kept (S: moved to <data directory>/replays/<level>-<time>.hrr) or watched
// (W); an unsaved one is deleted when the screen goes. The ghost: a first
// success becomes the level's ghost; an existing ghost is replaced only on
// the player's say (K: this run; G: the autopilot's line). Enter or R plays
// again, N the next level of the list, Escape goes back to the level select.

#include <filesystem>
#include <string>
#include <vector>

#include "game/trial/TrialJudge.h"
#include "game/ui/scores/ScoreStore.h"
#include "game/ui/hud/WindowRects.h"
#include "game/ui/screens/Screen.h"
#include "game/ui/screens/TrialEnding.h"

namespace hemiroll::game {

class ResultsScreen final : public Screen {
 public:
  ResultsScreen(ScreenHost& host, std::string levelPath, std::string levelName, TrialResult result,
                std::filesystem::path replay = {}, std::string replayNote = {}, bool assisted = false,
                TrialEnding ending = {});
  ~ResultsScreen() override;
  // The autopilot's run (or the part before the player took over): kept as the ghost to race.
  void raceThisLine();
  // The player's run replaces the level's ghost (K).
  void raceThisRun();
  // The level list in order (FreePlay::playlist): N plays the one after this.
  void setPlaylist(std::vector<std::string> playlist) { playlist_ = std::move(playlist); }
  // The next level's file, "" when this is the last (or there is no list).
  std::string nextLevel() const;
  const char* name() const override { return "results"; }
  void input(const platform::InputEvent& e) override;
  void update(double dt) override { shownFor_ += dt; }
  void paint() override;

  const TrialResult& result() const { return result_; }
  const std::filesystem::path& replay() const { return replay_; }
  bool replaySaved() const { return replaySaved_; }
  bool newBest() const { return newBest_; }
  const TrialEnding& ending() const { return ending_; }
  // Where the panel was drawn in the last frame (layout tests).
  const WindowRect& panelRect() const { return panelRect_; }

 private:
  void again();
  void next();
  void saveReplay();
  void watchReplay();
  bool offersRaceThisRun() const;
  std::string levelPath_, levelName_;
  TrialResult result_;
  std::filesystem::path replay_;  // the trial's replay log; "" = none
  std::string replayNote_;
  bool replaySaved_ = false;
  LevelBest before_;
  bool newBest_ = false;
  bool stored_ = false;
  bool assisted_ = false;  // the autopilot played: not in the scores, offered as a ghost
  bool ghostKept_ = false;  // this run is the level's ghost now
  std::vector<std::string> playlist_;
  TrialEnding ending_;
  WindowRect panelRect_;
  double shownFor_ = 0.0;  // [s] since the screen came up: the celebration's clock
};

}  // namespace hemiroll::game
