#pragma once
// The autopilot's hint as the player reads it: a compass at the bottom of
// the screen whose arrow points where the autopilot would move the proxy,
// in screen directions (right is the mouse's right, up its forward), its
// length the distance (full at kFullScale), with the distance in mm. The
// scene's green arrow says the same but can be small or hidden by the
// hemisphere; the compass is always in the same place and the same size.

#include <string>

#include "game/hud/WindowRects.h"

namespace hemiroll::game {

class HintCompass {
 public:
  static constexpr double kFullScale = 0.01;  // [m]: a centimetre or more fills the dial

  void hide() { shown_ = false; }
  // The wanted move of the proxy, in screen directions [m].
  void show(double right, double up);
  bool shown() const { return shown_; }
  double right() const { return right_; }
  double up() const { return up_; }

  // Inside an ImGui frame; notes its window in `rects` (the HUD's, for
  // layout checks) when given.
  void draw(WindowRects* rects = nullptr) const;

 private:
  bool shown_ = false;
  double right_ = 0.0, up_ = 0.0;
};

// The move (dx, dy) on the plane [m] in screen directions for a camera whose
// screen right points along `screenRightHeading` [rad] (render::screenRightHeading).
void toScreenDirections(double dx, double dy, double screenRightHeading, double& right, double& up);

}  // namespace hemiroll::game
