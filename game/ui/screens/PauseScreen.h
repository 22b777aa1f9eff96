#pragma once
// Pause, beside the play screen (which keeps being drawn, frozen: the servo
// loop got a Pause command, force zero at once; the frames slow to
// App::kStillFps). Continue (Escape, Enter),
// restart (R; not a research session's trial, which is recorded once), quit
// the trial (Q: it ends as a failure, "quit by the player", and the results
// screen follows, or the session screen for a session's trial).

#include <string>

#include "game/ui/screens/Screen.h"

namespace hemiroll::game {

class PlayScreen;

class PauseScreen final : public Screen {
 public:
  // `reason`: why play stopped when it was not the player (a safety fault).
  PauseScreen(ScreenHost& host, PlayScreen& play, std::string reason = {})
      : Screen(host), play_(play), reason_(std::move(reason)) {}
  const char* name() const override { return "pause"; }
  bool overlay() const override { return true; }
  FrameNeed frameNeed() const override { return FrameNeed::Still; }
  void input(const platform::InputEvent& e) override;
  void update(double dt) override;
  void paint() override;

 private:
  void resume();
  void restart();
  void watch();
  void quit();
  PlayScreen& play_;
  std::string reason_;
};

}  // namespace hemiroll::game
