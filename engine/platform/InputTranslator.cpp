#include "engine/platform/InputTranslator.h"

namespace hemiroll::platform {

namespace {

Key keyOf(SDL_Keycode code) {
  switch (code) {
    case SDLK_ESCAPE: return Key::Escape;
    case SDLK_RETURN:
    case SDLK_KP_ENTER: return Key::Enter;
    case SDLK_SPACE: return Key::Space;
    case SDLK_UP: return Key::Up;
    case SDLK_DOWN: return Key::Down;
    case SDLK_LEFT: return Key::Left;
    case SDLK_RIGHT: return Key::Right;
    case SDLK_TAB: return Key::Tab;
    case SDLK_BACKSPACE: return Key::Backspace;
    case SDLK_F1: return Key::F1;
    default: return Key::Other;
  }
}

PointerButton buttonOf(Uint8 button) {
  switch (button) {
    case SDL_BUTTON_LEFT: return PointerButton::Left;
    case SDL_BUTTON_MIDDLE: return PointerButton::Middle;
    case SDL_BUTTON_RIGHT: return PointerButton::Right;
    default: return PointerButton::None;
  }
}

}  // namespace

InputEvent translateEvent(const SDL_Event& event) {
  InputEvent out;
  out.timestamp = event.common.timestamp * 1e-3;  // SDL counts milliseconds
  switch (event.type) {
    case SDL_QUIT:
      out.type = InputType::Quit;
      break;
    case SDL_KEYDOWN:
    case SDL_KEYUP:
      out.type = event.type == SDL_KEYDOWN ? InputType::KeyDown : InputType::KeyUp;
      out.code = event.key.keysym.sym;
      out.key = keyOf(event.key.keysym.sym);
      out.repeat = event.key.repeat != 0;
      break;
    case SDL_MOUSEMOTION:
      out.type = InputType::PointerMove;
      out.x = event.motion.x;
      out.y = event.motion.y;
      out.dx = event.motion.xrel;
      out.dy = event.motion.yrel;
      break;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
      out.type = event.type == SDL_MOUSEBUTTONDOWN ? InputType::ButtonDown : InputType::ButtonUp;
      out.button = buttonOf(event.button.button);
      out.x = event.button.x;
      out.y = event.button.y;
      break;
    case SDL_MOUSEWHEEL: {
      out.type = InputType::Wheel;
      // "Flipped" devices report the opposite sign; normalise to "away = up".
      const double notches = event.wheel.y;
      out.wheel = event.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -notches : notches;
      break;
    }
    case SDL_WINDOWEVENT:
      if (event.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) {
        out.type = InputType::Resized;
        out.x = event.window.data1;
        out.y = event.window.data2;
      } else if (event.window.event == SDL_WINDOWEVENT_FOCUS_LOST) {
        out.type = InputType::FocusLost;
      }
      break;
    default:
      break;
  }
  return out;
}

}  // namespace hemiroll::platform
