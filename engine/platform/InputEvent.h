#pragma once
// Input as the engine sees it: a small plain struct, so screens, the HUD and
// their tests never include SDL. Positions are in window pixels (what the
// mouse device's PointerMapping expects), y growing downwards as on screen.

#include <cstdint>

namespace hemiroll::platform {

enum class InputType : std::uint8_t {
  None,          // an SDL event the engine does not use
  Quit,          // window closed or SIGINT
  KeyDown,
  KeyUp,
  PointerMove,
  ButtonDown,
  ButtonUp,
  Wheel,
  Resized,       // the window's size changed (x, y = new size [window px])
  FocusLost,     // pause-worthy: the player looked away
};

// Keys the game binds, by meaning of their usual place; everything else is
// Key::Other with its SDL keycode in `code` (for a key-binding screen).
enum class Key : std::uint8_t { Other, Escape, Enter, Space, Up, Down, Left, Right, Tab, Backspace, F1 };

enum class PointerButton : std::uint8_t { None, Left, Middle, Right };

struct InputEvent {
  InputType type = InputType::None;
  Key key = Key::Other;
  std::int32_t code = 0;                     // SDL keycode of a key event (Key::Other included)
  bool repeat = false;                       // a key held down repeats
  PointerButton button = PointerButton::None;
  double x = 0.0, y = 0.0;                   // pointer [window px], or new size for Resized
  double dx = 0.0, dy = 0.0;                 // PointerMove: motion since the last one [window px]
                                             // (also while the pointer is captured, when x, y stand still)
  double wheel = 0.0;                        // notches, positive away from the user
  double timestamp = 0.0;                    // [s] since SDL started
};

// A left-button pointer event at (x, y) [window px]: what scripted players
// and tests inject to move, press and release as a mouse would.
inline InputEvent leftPointerEvent(InputType type, double x, double y) {
  InputEvent e;
  e.type = type;
  e.x = x;
  e.y = y;
  e.button = PointerButton::Left;
  return e;
}

}  // namespace hemiroll::platform
