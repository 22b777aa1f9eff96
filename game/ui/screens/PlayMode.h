#pragma once
// What kind of trial the play screen runs, injected into it: free play of a
// level file (FreePlay: the player's settings, a replay log, the ghost,
// restart, the results screen) or a research session's next trial
// (SessionTrialPlay: the plan's level and overrides, recorded into the
// session folder, no ghost, no restart, the session screen hears how it
// went). PlayScreen itself only plays: device, scene, HUD, sound, pause.

#include <memory>
#include <string>

#include "engine/physics/ForceCoupling.h"
#include "engine/script/LevelLoader.h"
#include "game/play/PlaySession.h"
#include "game/ui/screens/TrialEnding.h"
#include "game/trial/TrialJudge.h"

namespace hemiroll::game {

class ScreenHost;

class PlayMode {
 public:
  virtual ~PlayMode() = default;

  // The level file (for the ghost, which checks the replay's level hash).
  virtual const std::string& levelPath() const = 0;
  // Loads the level into `level`, completes `def` (which carries the
  // player's device) and makes the session. Throws std::exception with a
  // message for the player when the trial cannot start.
  virtual std::unique_ptr<PlaySession> begin(script::LoadedLevel& level, PlaySessionDef& def) = 0;
  // The coupling the trial runs with (the HUD shows its method).
  virtual physics::CouplingDef coupling(const task::LevelDef& level) const = 0;
  // The HUD's title.
  virtual std::string title(const task::LevelDef& level) const = 0;
  virtual bool ghostAllowed() const = 0;
  virtual bool restartAllowed() const = 0;
  // The judge ended the trial (`session` finished, its result in `result`,
  // the last frame and what decided it in `ending`): the mode changes the
  // screen stack.
  virtual void finished(PlaySession& session, TrialResult result, const task::LevelDef& level,
                        TrialEnding ending) = 0;
  // The trial could not start (`error`) and the player left.
  virtual void leftWithoutTrial(const std::string& error) = 0;
};

}  // namespace hemiroll::game
