#pragma once
// Research session: the participant id every trial is stored under in the
// scores database, and where the data goes (the data directory and the
// database file). Escape goes back. Recording played trials (engine/record)
// from the window is not wired yet: `hemiroll run --record` records.

#include <array>

#include "game/screens/Screen.h"

namespace hemiroll::game {

class ResearchScreen final : public Screen {
 public:
  using Screen::Screen;
  const char* name() const override { return "research"; }
  void enter() override;
  void leave() override;
  void input(const platform::InputEvent& e) override;
  void paint() override;

 private:
  std::array<char, 64> participant_{};
};

}  // namespace hemiroll::game
