#pragma once
// Playing a level: a PlaySession (servo loop on its own thread with the
// mouse), drawn every frame from the latest snapshot through
// RenderSceneBuilder and engine/render, with the PlayHud over it.
// Mouse: the proxy starts on the mass point and moves by the mouse's strokes
// (captured pointer, the proxy drawn as the cursor: PointerMapping.h says
// why); left click or the take-hold key = take hold (the proxy is put on the
// mass point and the force ramps in), right click = let go, wheel = proxy
// height; the arrow keys turn the orbit camera. The clock starts when the
// player first takes hold (PlaySession); a prompt says so, and says to take
// hold again after letting go. With the ghost on (settings), the player's
// best run of the level (its replay) is played in step with this one, by
// simulated time, and drawn translucent beside it. Keys: Escape pauses (as
// does the window losing focus), Tab changes the camera, I shows every
// judged component. When the judge ends the trial the results screen takes
// this one's place.
//
// What kind of trial it is (free play, a research session's trial) is a
// PlayMode given to it (PlayMode.h): loading, titles, ghost and restart
// rules and what follows the end are the mode's.

#include <memory>
#include <optional>
#include <string>

#include "engine/render/ContactTrace.h"
#include "engine/render/RenderScene.h"
#include "engine/script/LevelLoader.h"
#include "game/ui/settings/KeyBindings.h"
#include "game/ui/hud/EdgePulse.h"
#include "game/ui/hud/FloorInset.h"
#include "game/ui/hud/HintCompass.h"
#include "game/ui/hud/PlayHud.h"
#include "game/play/PlaySession.h"
#include "game/ui/screens/PlayMode.h"
#include "game/ui/screens/Screen.h"
#include "game/play/ReplayPlayer.h"
#include "game/trial/GhostFile.h"

namespace hemiroll::game {

class PlayScreen final : public Screen {
 public:
  PlayScreen(ScreenHost& host, std::unique_ptr<PlayMode> mode);
  // Free play of a level file (FreePlay).
  PlayScreen(ScreenHost& host, std::string levelPath);
  ~PlayScreen() override;
  const char* name() const override { return "play"; }
  FrameNeed frameNeed() const override;
  void enter() override;
  void leave() override;
  void input(const platform::InputEvent& e) override;
  void update(double dt) override;
  void paint() override;

  // From the pause screen.
  void resume();
  void restart();
  // Free play only: the trial starts again with the autopilot holding the
  // proxy; a click or the take-hold key takes over.
  void watchAutopilot();
  void quit();
  void drainWhilePaused() {
    if (session_) session_->frame();
  }

  PlaySession* session() { return session_.get(); }
  const ReplayPlayer* ghost() const { return ghost_.get(); }
  bool restartAllowed() const { return mode_->restartAllowed(); }
  const PlayHud& hud() const { return hud_; }
  const HintCompass& compass() const { return compass_; }
  const EdgePulse& pulse() const { return pulse_; }
  const std::string& error() const { return error_; }

 private:
  void begin();
  void loadGhost();
  void keyAction(KeyAction action, bool repeat);
  // update()'s parts, in their order within a frame.
  void pollScore(double dt);
  void followGhost(const haptics::ServoSnapshot& s);
  void buildScene(const haptics::ServoSnapshot& s);
  void showAutopilot();
  void playSounds(const haptics::ServoSnapshot& s);
  void showForceCues(const haptics::ServoSnapshot& s, double dt);
  void silenceForceCues();
  bool safetyStop();
  void showGoal();
  std::string prompt() const;
  void endTrial();
  void back();
  void pause();

  std::unique_ptr<PlayMode> mode_;
  std::string error_;  // the level failed to load or the loop refused it
  script::LoadedLevel level_;
  std::unique_ptr<PlaySession> session_;
  std::unique_ptr<ReplayPlayer> ghost_;
  std::optional<double> ghostTime_;  // [s] the ghost's judged time, when kept with it
  GhostOwner ghostOwner_ = GhostOwner::Player;
  PlayHud hud_;
  HintCompass compass_;  // the autopilot's hint in screen directions
  FloorInset inset_;     // the targets and zones round the contact point, magnified
  EdgePulse pulse_;      // the warning before the mass point leaves the face
  render::RenderScene scene_;
  render::ContactTrace trace_;
  haptics::Engagement lastEngagement_ = haptics::Engagement::Disengaged;
  bool started_ = false;
  double scoreClock_ = 0.0;  // [s] since the running score was last asked for
  bool showHint_ = false;    // the hint key toggles the autopilot's hint
  int goalStage_ = -2;       // the stage whose goal the HUD shows (-2: none yet)
};

}  // namespace hemiroll::game
