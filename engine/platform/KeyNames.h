#pragma once
// Key codes by name, for key bindings a player reads and a settings file
// stores ("Space", "H", "Left", "Keypad 5"): SDL's own names, so that what the
// settings screen shows is what SDL reports for the key on this keyboard.
// Pure lookups in SDL's tables: no window and no SDL_Init needed. SDL stays
// out of this header, as out of InputEvent.h.

#include <cstdint>
#include <string>

#include "engine/platform/InputEvent.h"

namespace hemiroll::platform {

// The name of a key code (InputEvent::code); "" for an unknown code.
std::string keyName(std::int32_t code);
// The key code of a name as keyName writes it (case-insensitive for
// letters); 0 (no key) for a name SDL does not know.
std::int32_t keyFromName(const std::string& name);

// The KeyDown event the window gives for the key of that name, made the way
// it makes real ones (translateEvent): synthetic input for the screen tour
// and the tests, with the engine's Key and SDL's code as a player's would have.
InputEvent keyDownEvent(const std::string& name);

}  // namespace hemiroll::platform
