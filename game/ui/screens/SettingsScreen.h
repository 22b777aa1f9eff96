#pragma once
// Settings: device (the mouse's sensitivity and feel), force cues, force method and gains (the
// level's, or the player's override), keys (each play action's key: click
// it, press the new one), audio volume, graphics (vsync, frame cap,
// interface scale, camera, zoom). Changes apply at once
// (volume, vsync, frame cap, interface scale, keys) or from the next trial
// (device, mouse sensitivity, coupling, camera),
// and are saved (settings.json) when the screen is left. Escape goes back,
// or cancels a key being changed.

#include <optional>
#include <string>

#include "game/ui/settings/KeyBindings.h"
#include "game/ui/settings/Settings.h"
#include "game/ui/screens/Screen.h"

namespace hemiroll::game {

class SettingsScreen final : public Screen {
 public:
  using Screen::Screen;
  const char* name() const override { return "settings"; }
  void leave() override;
  void input(const platform::InputEvent& e) override;
  void paint() override;

  // The next key pressed is bound to `action` (what its button does).
  void listenFor(KeyAction action);
  std::optional<KeyAction> listening() const { return listening_; }
  const std::string& keyNote() const { return keyNote_; }

 private:
  void paintKeys();
  // The panel's sections, in the order paint() shows them.
  void paintDevice(Settings& s);
  void paintForceCues(Settings& s);
  void paintForceMethod(Settings& s);
  void paintAudio(Settings& s);
  void paintGraphics(Settings& s);

  std::optional<KeyAction> listening_;
  std::string keyNote_;  // what the last key change did (a swap, a refusal)
};

}  // namespace hemiroll::game
