#pragma once
// Which key does what while playing: the player's to change on the settings
// screen, kept in settings.json under "keys" by name (KeyNames.h). Menus
// keep their fixed keys (arrows, Enter); Escape is never bindable: it always
// pauses or goes back, so a player cannot lock themselves out of the menus.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace hemiroll::game {

enum class KeyAction : std::uint8_t {
  TakeHold, LetGo, CycleCamera, OrbitLeft, OrbitRight, OrbitUp, OrbitDown, Hint, HudTable
};
inline constexpr int kKeyActionCount = 9;

struct KeyActionInfo {
  const char* id;          // the key under "keys" in settings.json
  const char* label;       // what the settings screen calls it
  const char* defaultKey;  // a name keyFromName knows
};
const KeyActionInfo& keyActionInfo(KeyAction action);

class KeyBindings {
 public:
  KeyBindings();  // the defaults

  std::int32_t key(KeyAction action) const { return keys_[index(action)]; }
  std::string keyName(KeyAction action) const;
  std::optional<KeyAction> actionOf(std::int32_t code) const;

  // Binds `code` to `action`. The action that had `code` gets `action`'s old
  // key: a swap, so that no key does two things and no action is left
  // without one. False (and nothing changed) for Escape, no key, or a key
  // without a name that finds it again (it could not be saved).
  bool bind(KeyAction action, std::int32_t code);
  static bool bindable(std::int32_t code);

  bool operator==(const KeyBindings&) const = default;

 private:
  static int index(KeyAction a) { return static_cast<int>(a); }
  std::array<std::int32_t, kKeyActionCount> keys_{};
};

// A text for the player with "{key:ACTION}" (ACTION a KeyActionInfo id:
// take_hold, let_go, hint, ...) replaced by the key now bound to it, so that
// a level's description or message names the player's key, not the default
// (issue 27: the hint rebound to J, the text still said H). Anything else in
// braces is left as written.
std::string withKeyNames(const std::string& text, const KeyBindings& keys);

}  // namespace hemiroll::game
