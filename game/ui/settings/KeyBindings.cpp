#include "game/ui/settings/KeyBindings.h"

#include "engine/platform/KeyNames.h"

#include <string_view>

namespace hemiroll::game {

namespace {
// Space takes hold as in the paper's experiments (Sec. 4): the hand stays on
// the device. Backspace lets go, away from Space so that a fumble does not
// undo a take.
constexpr KeyActionInfo kActions[kKeyActionCount] = {
    {"take_hold", "take hold", "Space"},  {"let_go", "let go", "Backspace"},
    {"camera", "next camera", "Tab"},     {"orbit_left", "orbit left", "Left"},
    {"orbit_right", "orbit right", "Right"}, {"orbit_up", "orbit up", "Up"},
    {"orbit_down", "orbit down", "Down"}, {"hint", "autopilot hint", "H"},
    {"hud_table", "HUD table", "I"}};
}  // namespace

const KeyActionInfo& keyActionInfo(KeyAction action) { return kActions[static_cast<int>(action)]; }

KeyBindings::KeyBindings() {
  for (int i = 0; i < kKeyActionCount; ++i) keys_[i] = platform::keyFromName(kActions[i].defaultKey);
}

std::string KeyBindings::keyName(KeyAction action) const { return platform::keyName(key(action)); }

std::optional<KeyAction> KeyBindings::actionOf(std::int32_t code) const {
  if (code == 0) return std::nullopt;
  for (int i = 0; i < kKeyActionCount; ++i)
    if (keys_[i] == code) return static_cast<KeyAction>(i);
  return std::nullopt;
}

// A key must also have a name that finds it again, so that settings.json
// gives back exactly the keys it was saved with.
bool KeyBindings::bindable(std::int32_t code) {
  if (code == 0 || code == platform::keyFromName("Escape")) return false;
  const std::string name = platform::keyName(code);
  return !name.empty() && platform::keyFromName(name) == code;
}

bool KeyBindings::bind(KeyAction action, std::int32_t code) {
  if (!bindable(code)) return false;
  if (const std::optional<KeyAction> holder = actionOf(code)) keys_[index(*holder)] = key(action);
  keys_[index(action)] = code;
  return true;
}

std::string withKeyNames(const std::string& text, const KeyBindings& keys) {
  static constexpr std::string_view kOpen = "{key:";
  std::string out;
  std::size_t at = 0;
  while (true) {
    const std::size_t open = text.find(kOpen, at);
    const std::size_t close = open == std::string::npos ? open : text.find('}', open);
    if (close == std::string::npos) break;
    const std::string_view id(text.data() + open + kOpen.size(), close - open - kOpen.size());
    std::optional<KeyAction> action;
    for (int i = 0; i < kKeyActionCount; ++i)
      if (id == kActions[i].id) action = static_cast<KeyAction>(i);
    out.append(text, at, open - at);
    if (action)
      out += keys.keyName(*action);
    else
      out.append(text, open, close + 1 - open);
    at = close + 1;
  }
  out.append(text, at, std::string::npos);
  return out;
}

}  // namespace hemiroll::game
