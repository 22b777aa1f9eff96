#pragma once
// A research session in the window (docs/PROTOCOLS.md): between the trials
// of a ResearchSession. It opens (or resumes) the session, then shows the
// next trial - its block, condition, level and coupling, the block's
// instructions, the break before it with the time left of its minimum
// duration - and plays it in a PlayScreen (session mode: recorded into the
// session folder, results row appended when it ends). A break that ends the
// sitting, the end of the session and any error are shown here. Keys: Enter
// starts the next trial (once a break's minimum has passed), Escape goes
// back (the session resumes when started again).

#include <memory>
#include <string>
#include <vector>

#include "game/research/session/ResearchSession.h"
#include "game/ui/screens/Screen.h"

namespace hemiroll::game {

struct SessionTrialEnd;

class SessionScreen final : public Screen {
 public:
  enum class Stage { Error, Break, Ready, Stopped, Complete };

  SessionScreen(ScreenHost& host, SessionRequest request);
  ~SessionScreen() override;
  const char* name() const override { return "session"; }
  void enter() override;
  void input(const platform::InputEvent& e) override;
  void update(double dt) override;
  void paint() override;

  Stage stage() const;
  const ResearchSession* session() const { return session_.get(); }
  const std::string& error() const { return error_; }
  // One line per trial played in this sitting ("trial-001: success, target held, 9.4 s").
  const std::vector<std::string>& log() const { return log_; }

 private:
  void open();
  void startTrial();
  void trialEnded(const SessionTrialEnd& end);
  void armBreak();
  void paintNext(Stage stage);

  SessionRequest request_;
  std::unique_ptr<ResearchSession> session_;
  std::string error_;
  bool opened_ = false;
  int breakFor_ = 0;          // the trial index whose break timer runs (0 = none)
  double breakLeft_ = 0.0;    // [s] of the break's minimum still to wait
  std::vector<std::string> log_;
};

}  // namespace hemiroll::game
