#pragma once
// Watching a replay: a ReplayPlayer plays the log as many ticks per frame as
// wall time asks (1x speed). The level file must hash as logged; otherwise
// the screen says so. Escape or Enter goes back.

#include <memory>
#include <string>

#include "engine/render/ContactTrace.h"
#include "engine/render/RenderScene.h"
#include "engine/script/LevelLoader.h"
#include "game/play/ReplayPlayer.h"
#include "game/screens/Screen.h"

namespace hemiroll::game {

class ReplayScreen final : public Screen {
 public:
  ReplayScreen(ScreenHost& host, std::string levelPath, std::string replayFile);
  ~ReplayScreen() override;
  const char* name() const override { return "replay"; }
  void enter() override;
  void input(const platform::InputEvent& e) override;
  void update(double dt) override;
  void paint() override;

  const std::string& error() const { return error_; }
  std::size_t ticksPlayed() const { return player_ ? player_->ticksPlayed() : 0; }
  std::size_t ticksTotal() const { return player_ ? player_->ticksTotal() : 0; }

 private:
  std::string levelPath_, replayFile_, error_;
  script::LoadedLevel level_;
  std::unique_ptr<ReplayPlayer> player_;
  double clock_ = 0.0;  // [s] of wall time watched
  render::RenderScene scene_;
  render::ContactTrace trace_;
};

}  // namespace hemiroll::game
