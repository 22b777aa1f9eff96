#pragma once
// The end of a trial: outcome and reason, time, score, medal, the personal
// best before this trial, and whether it is a new one. The trial is stored
// in the scores database when the screen is made. Enter plays again,
// Escape goes back to the level select.

#include <string>

#include "game/play/HeadlessTrial.h"
#include "game/scores/ScoreStore.h"
#include "game/screens/Screen.h"

namespace hemiroll::game {

class ResultsScreen final : public Screen {
 public:
  ResultsScreen(App& app, std::string levelPath, std::string levelName, TrialResult result);
  const char* name() const override { return "results"; }
  void input(const platform::InputEvent& e) override;
  void paint() override;

  const TrialResult& result() const { return result_; }
  bool newBest() const { return newBest_; }

 private:
  void again();
  std::string levelPath_, levelName_;
  TrialResult result_;
  LevelBest before_;
  bool newBest_ = false;
  bool stored_ = false;
};

}  // namespace hemiroll::game
