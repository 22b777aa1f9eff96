#pragma once
// Watching a replay: the log's device readings played back through
// ReplayDevice into a ServoLoop built from the level, on this thread, as many
// ticks per frame as wall time asks (1x speed), each logged command posted
// before the tick that applied it (ReplayRunner's rule, one frame at a time).
// The level file must hash as logged; otherwise the screen says so.
// Escape or Enter goes back. Ghost racing (a replay beside live play) is not
// done.

#include <memory>
#include <string>

#include "engine/haptics/ReplayDevice.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/record/ReplayReader.h"
#include "engine/render/ContactTrace.h"
#include "engine/render/RenderScene.h"
#include "engine/script/LevelLoader.h"
#include "game/screens/Screen.h"

namespace hemiroll::game {

class ReplayScreen final : public Screen {
 public:
  ReplayScreen(App& app, std::string levelPath, std::string replayFile);
  ~ReplayScreen() override;
  const char* name() const override { return "replay"; }
  void enter() override;
  void input(const platform::InputEvent& e) override;
  void update(double dt) override;
  void paint() override;

  const std::string& error() const { return error_; }
  std::size_t ticksPlayed() const { return next_; }
  std::size_t ticksTotal() const { return log_.inputs.size(); }

 private:
  std::string levelPath_, replayFile_, error_;
  script::LoadedLevel level_;
  record::ReplayLog log_;
  std::unique_ptr<haptics::ReplayDevice> device_;
  std::unique_ptr<haptics::ServoLoop> loop_;
  std::size_t next_ = 0, nextCommand_ = 0;
  double clock_ = 0.0;  // [s] of wall time watched
  haptics::ServoSnapshot snapshot_;
  render::RenderScene scene_;
  render::ContactTrace trace_;
};

}  // namespace hemiroll::game
