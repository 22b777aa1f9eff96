#pragma once
// SDL_Event -> InputEvent. Pure (no window, no video subsystem), so it is
// tested with synthetic SDL events. Kept out of InputEvent.h so that only
// this file and Window.cpp include SDL.

#include <SDL.h>

#include "engine/platform/InputEvent.h"

namespace hemiroll::platform {

// Events the engine does not use come back as InputType::None.
InputEvent translateEvent(const SDL_Event& event);

}  // namespace hemiroll::platform
