#pragma once
// Settings: device, force method and gains (the level's, or the player's
// override), keys (shown), audio volume, graphics (vsync, camera, zoom).
// Changes apply at once (volume, vsync) or from the next trial (device,
// coupling, camera), and are saved (settings.json) when the screen is left.
// Escape goes back.

#include "game/screens/Screen.h"

namespace hemiroll::game {

class SettingsScreen final : public Screen {
 public:
  using Screen::Screen;
  const char* name() const override { return "settings"; }
  void leave() override;
  void input(const platform::InputEvent& e) override;
  void paint() override;
};

}  // namespace hemiroll::game
