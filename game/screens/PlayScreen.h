#pragma once
// Playing a level: a PlaySession (servo loop on its own thread with the
// mouse), drawn every frame from the latest snapshot through
// RenderSceneBuilder and engine/render, with the PlayHud over it.
// Mouse: the proxy starts on the mass point and moves by the mouse's strokes
// (captured pointer, the proxy drawn as the cursor: PointerMapping.h says
// why), left click = take hold (engages near the mass point), right click =
// let go, wheel = proxy height; the arrow keys turn the orbit camera. With the ghost on (settings), the player's
// best run of the level (its replay) is played in step with this one, by
// simulated time, and drawn translucent beside it. Keys: Escape pauses
// (as does the window losing focus), Tab changes the camera. When the judge
// ends the trial the results screen takes this one's place.
//
// A research session's trial (SessionScreen) plays the session's next trial
// instead: its level with the plan's overrides and seed (the settings'
// override is not used), recorded into the session folder (trial CSV and
// sidecar through the loop's ring, the replay log beside them), no restart;
// when it ends the results row is appended, the screen goes and `done` says
// how it went (no results screen, no scores).

#include <functional>
#include <optional>
#include <memory>
#include <string>

#include "engine/render/ContactTrace.h"
#include "engine/render/RenderScene.h"
#include "engine/script/LevelLoader.h"
#include "game/app/KeyBindings.h"
#include "game/hud/PlayHud.h"
#include "game/play/PlaySession.h"
#include "game/trial/ReplayPlayer.h"
#include "game/screens/Screen.h"

namespace hemiroll::game {

class ResearchSession;
class TrialRecording;

// How a session's trial ended: recorded (its result), or not (why).
struct SessionTrialEnd {
  bool recorded = false;
  TrialResult result;
  std::string error;
};

class PlayScreen final : public Screen {
 public:
  PlayScreen(App& app, std::string levelPath);
  PlayScreen(App& app, ResearchSession& session, std::function<void(const SessionTrialEnd&)> done);
  ~PlayScreen() override;
  const char* name() const override { return "play"; }
  void enter() override;
  void leave() override;
  void input(const platform::InputEvent& e) override;
  void update(double dt) override;
  void paint() override;

  // From the pause screen.
  void resume();
  void restart();
  void quit();
  void drainWhilePaused() {
    if (session_) session_->frame();
  }

  PlaySession* session() { return session_.get(); }
  const ReplayPlayer* ghost() const { return ghost_.get(); }
  bool inResearchSession() const { return research_ != nullptr; }
  const PlayHud& hud() const { return hud_; }
  const std::string& error() const { return error_; }

 private:
  void begin();
  void loadGhost();
  void keyAction(KeyAction action, bool repeat);
  void beginSessionTrial(PlaySessionDef& def);
  void endSessionTrial(SessionTrialEnd end);
  void back();
  void pause();

  std::string levelPath_;
  std::string error_;  // the level failed to load or the loop refused it
  script::LoadedLevel level_;
  std::unique_ptr<PlaySession> session_;
  std::unique_ptr<ReplayPlayer> ghost_;
  PlayHud hud_;
  render::RenderScene scene_;
  render::ContactTrace trace_;
  haptics::Engagement lastEngagement_ = haptics::Engagement::Disengaged;
  bool started_ = false;
  double scoreClock_ = 0.0;  // [s] since the running score was last asked for
  ResearchSession* research_ = nullptr;  // set: a research session's trial
  std::function<void(const SessionTrialEnd&)> sessionDone_;
  std::unique_ptr<TrialRecording> recording_;
  bool sessionEnded_ = false;
};

}  // namespace hemiroll::game
