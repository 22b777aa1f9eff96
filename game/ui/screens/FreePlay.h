#pragma once
// Free play of a level file (PlayMode.h): the player's coupling override
// from the settings, the last trial logged for a replay (unless the force
// method is overridden: a replay repeats the level's own loop), the ghost,
// restart, and the results screen at the end.

#include <string>
#include <vector>

#include "game/ui/screens/PlayMode.h"

namespace hemiroll::game {

class FreePlay final : public PlayMode {
 public:
  // `watch`: the autopilot plays and the player may take over (no score, no best).
  FreePlay(ScreenHost& host, std::string levelPath, bool watch = false)
      : host_(host), levelPath_(std::move(levelPath)), watch_(watch) {}
  bool watching() const { return watch_; }
  // The level list's playable files in order (LevelSelectScreen::playlist):
  // the results screen offers the one after this level. Empty: no "next".
  void setPlaylist(std::vector<std::string> playlist) { playlist_ = std::move(playlist); }
  const std::vector<std::string>& playlist() const { return playlist_; }

  const std::string& levelPath() const override { return levelPath_; }
  std::unique_ptr<PlaySession> begin(script::LoadedLevel& level, PlaySessionDef& def) override;
  physics::CouplingDef coupling(const task::LevelDef& level) const override;
  std::string title(const task::LevelDef& level) const override { return level.name; }
  bool ghostAllowed() const override { return true; }
  bool restartAllowed() const override { return true; }
  void finished(PlaySession& session, TrialResult result, const task::LevelDef& level,
                TrialEnding ending) override;
  void leftWithoutTrial(const std::string& error) override;

 private:
  ScreenHost& host_;
  std::string levelPath_;
  bool watch_ = false;
  std::vector<std::string> playlist_;
};

}  // namespace hemiroll::game
