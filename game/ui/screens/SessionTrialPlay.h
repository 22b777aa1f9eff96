#pragma once
// A research session's next trial in the window (PlayMode.h): its level
// with the plan's overrides and seed (the settings' override is not used),
// recorded into the session folder (trial CSV and sidecar through the
// trial rig's record tap, the replay log beside them), no ghost (a condition
// the protocol did not ask for), no restart (a trial is recorded once).
// When it ends the results row is appended, the play screen goes and
// `done` says how it went (no results screen, no scores).

#include <functional>

#include "game/ui/screens/PlayMode.h"

namespace hemiroll::game {

class ResearchSession;
class TrialRecording;

// How a session's trial ended: recorded (its result), or not (why).
struct SessionTrialEnd {
  bool recorded = false;
  TrialResult result;
  std::string error;
};

class SessionTrialPlay final : public PlayMode {
 public:
  SessionTrialPlay(ScreenHost& host, ResearchSession& session, std::function<void(const SessionTrialEnd&)> done);
  ~SessionTrialPlay() override;

  const std::string& levelPath() const override { return levelPath_; }
  std::unique_ptr<PlaySession> begin(script::LoadedLevel& level, PlaySessionDef& def) override;
  physics::CouplingDef coupling(const task::LevelDef& level) const override { return level.coupling; }
  // The player sees where they are in the plan.
  std::string title(const task::LevelDef& level) const override;
  bool ghostAllowed() const override { return false; }
  bool restartAllowed() const override { return false; }
  void finished(PlaySession& session, TrialResult result, const task::LevelDef& level,
                TrialEnding ending) override;
  void leftWithoutTrial(const std::string& error) override;

 private:
  void end(SessionTrialEnd end, const PlaySession* session);

  ScreenHost& host_;
  ResearchSession& research_;
  std::string levelPath_;
  std::function<void(const SessionTrialEnd&)> done_;
  std::unique_ptr<TrialRecording> recording_;
  bool ended_ = false;
};

}  // namespace hemiroll::game
