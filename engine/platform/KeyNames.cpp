#include "engine/platform/KeyNames.h"

#include <SDL.h>

#include "engine/platform/InputTranslator.h"

namespace hemiroll::platform {

std::string keyName(std::int32_t code) {
  if (code == SDLK_UNKNOWN) return "";
  return SDL_GetKeyName(static_cast<SDL_Keycode>(code));  // SDL's buffer: copied at once
}

std::int32_t keyFromName(const std::string& name) {
  if (name.empty()) return SDLK_UNKNOWN;
  return SDL_GetKeyFromName(name.c_str());
}

InputEvent keyDownEvent(const std::string& name) {
  SDL_Event e{};
  e.type = SDL_KEYDOWN;
  e.key.keysym.sym = keyFromName(name);
  return translateEvent(e);
}

}  // namespace hemiroll::platform
