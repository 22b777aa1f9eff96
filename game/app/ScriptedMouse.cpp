#include "game/app/ScriptedMouse.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "game/app/App.h"

namespace hemiroll::game {

namespace {

platform::InputEvent pointerEvent(platform::InputType type, double x, double y) {
  platform::InputEvent e;
  e.type = type;
  e.x = x;
  e.y = y;
  e.button = platform::PointerButton::Left;
  return e;
}

}  // namespace

void ScriptedMouse::step(App& app, double t) {
  const platform::PixelSize size = app.window().windowSize();
  const double cx = size.width / 2.0, cy = size.height / 2.0;
  if (t < def_.clickAt) {
    app.inject(pointerEvent(platform::InputType::PointerMove, cx, cy));
    return;
  }
  if (!clicked_) {
    app.inject(pointerEvent(platform::InputType::ButtonDown, cx, cy));
    app.inject(pointerEvent(platform::InputType::ButtonUp, cx, cy));
    clicked_ = true;
    return;
  }
  const double since = t - def_.clickAt;
  const double r = def_.radius * std::min(1.0, since);  // eased in over 1 s
  const double a = 2.0 * std::numbers::pi * since / def_.period;
  app.inject(pointerEvent(platform::InputType::PointerMove, cx + r * std::cos(a), cy + r * std::sin(a)));
}

}  // namespace hemiroll::game
