#pragma once
// Watching a replay: a ReplayPlayer plays the log as many ticks per frame as
// wall time asks, at the chosen speed (1/8x to 4x: slow motion shows what
// a hand did in a second), with what play showed to read it by: the target
// and the contact trace in the scene, the magnified floor (FloorInset) with
// the proxy's path drawn over the contact's, and a panel with the clock, the
// speed and the keys. The level file must hash as logged; otherwise the
// screen says so.
// Keys: Down/Up (or - and +) halve and double the speed, Space pauses,
// Home (or R) plays it from the start, Escape or Enter goes back.

#include <memory>
#include <optional>
#include <string>

#include "engine/render/ContactTrace.h"
#include "engine/render/RenderScene.h"
#include "engine/script/LevelLoader.h"
#include "engine/task/TaskJudge.h"
#include "game/ui/hud/FloorInset.h"
#include "game/play/ReplayPlayer.h"
#include "game/ui/screens/Screen.h"

namespace hemiroll::game {

class ReplayScreen final : public Screen {
 public:
  static constexpr double kSlowest = 0.125, kFastest = 4.0;

  ReplayScreen(ScreenHost& host, std::string levelPath, std::string replayFile);
  ~ReplayScreen() override;
  const char* name() const override { return "replay"; }
  FrameNeed frameNeed() const override { return FrameNeed::Play; }
  void enter() override;
  void input(const platform::InputEvent& e) override;
  void update(double dt) override;
  void paint() override;

  const std::string& error() const { return error_; }
  std::size_t ticksPlayed() const { return player_ ? player_->ticksPlayed() : 0; }
  std::size_t ticksTotal() const { return player_ ? player_->ticksTotal() : 0; }
  double speed() const { return speed_; }
  bool paused() const { return paused_; }
  const render::ContactTrace& proxyPath() const { return proxyPath_; }

 private:
  void open();
  std::string levelPath_, replayFile_, error_;
  script::LoadedLevel level_;
  std::unique_ptr<ReplayPlayer> player_;
  std::optional<task::TaskJudge> judge_;  // the stage whose target is drawn
  double clock_ = 0.0;  // [s] of replay time watched (wall time times the speed)
  double speed_ = 1.0;
  bool paused_ = false;
  render::RenderScene scene_;
  render::ContactTrace trace_;
  render::ContactTrace proxyPath_{render::ContactTraceDef{.capacity = 4096, .minSpacing = 2e-4, .fadeTime = 20.0}};
  FloorInset inset_;
};

}  // namespace hemiroll::game
