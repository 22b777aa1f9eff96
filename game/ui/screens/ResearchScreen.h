#pragma once
// Research: run a protocol (docs/PROTOCOLS.md) for a participant. Lists the
// protocols in <levels>/protocols/ (a broken one with its error), takes the
// participant and session ids, shows where the data goes and whether the
// session is new, resumes (k of N trials done) or is refused (a protocol
// changed since it started), and starts it in a SessionScreen. Keys: Up/Down
// choose the protocol, Enter starts, Escape goes back.

#include <array>
#include <string>
#include <vector>

#include "game/research/session/ResearchSession.h"
#include "game/ui/screens/ListingBudget.h"
#include "game/ui/screens/Screen.h"

namespace hemiroll::game {

struct ProtocolEntry {
  std::string path;
  std::string experiment;   // the file name when broken
  std::string description;
  int trials = 0;
  std::string error;        // "" = loads
};

// The protocols in `dir` (*.lua), sorted by file name.
// Each within `budget` (ListingBudget.h); those the time did not reach say so.
std::vector<ProtocolEntry> scanProtocols(const std::string& dir, const ListingBudget& budget = {});

class ResearchScreen final : public Screen {
 public:
  using Screen::Screen;
  const char* name() const override { return "research"; }
  void enter() override;
  void leave() override;
  void input(const platform::InputEvent& e) override;
  void paint() override;

  const std::vector<ProtocolEntry>& protocols() const { return protocols_; }
  int selected() const { return selected_; }
  // What starting the selected protocol would do, in one sentence.
  const std::string& status() const { return status_; }
  bool canStart() const { return canStart_; }

 private:
  void refresh();  // the status of the selected protocol, participant and session
  void start();
  void select(int index);
  SessionRequest requestFor(const std::string& protocol) const;
  std::vector<ProtocolEntry> protocols_;
  int selected_ = 0;
  std::array<char, 65> participant_{};
  std::array<char, 65> session_{};
  std::string status_;
  bool canStart_ = false;
};

}  // namespace hemiroll::game
