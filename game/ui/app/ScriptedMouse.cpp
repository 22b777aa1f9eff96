#include "game/ui/app/ScriptedMouse.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "game/ui/app/App.h"

namespace hemiroll::game {

void ScriptedMouse::step(App& app, double t) {
  // The proxy starts on the mass point: take hold there, then stroke the
  // circle (as motion: the play screen steers by the mouse's strokes).
  if (t < def_.clickAt) return;
  if (!clicked_) {
    app.inject(platform::leftPointerEvent(platform::InputType::ButtonDown, 0.0, 0.0));
    app.inject(platform::leftPointerEvent(platform::InputType::ButtonUp, 0.0, 0.0));
    clicked_ = true;
    return;
  }
  const double since = t - def_.clickAt;
  const double r = def_.radius * std::min(1.0, since);  // eased in over 1 s
  const double a = 2.0 * std::numbers::pi * since / def_.period;
  const double x = r * std::cos(a), y = r * std::sin(a);
  platform::InputEvent move = platform::leftPointerEvent(platform::InputType::PointerMove, 0.0, 0.0);
  move.dx = x - lastX_;
  move.dy = y - lastY_;
  lastX_ = x;
  lastY_ = y;
  app.inject(move);
}

}  // namespace hemiroll::game
