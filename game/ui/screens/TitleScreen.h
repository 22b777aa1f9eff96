#pragma once
// The title: play, settings, research session, quit. Keys: Enter plays,
// S settings, R research, Escape or Q quits.

#include "game/ui/screens/Screen.h"

namespace hemiroll::game {

class TitleScreen final : public Screen {
 public:
  using Screen::Screen;
  const char* name() const override { return "title"; }
  void input(const platform::InputEvent& e) override;
  void paint() override;

 private:
  void play();
  void settings();
  void research();
};

}  // namespace hemiroll::game
