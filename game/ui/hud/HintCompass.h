#pragma once
// The autopilot's hint as the player reads it, at the bottom of the screen,
// in screen directions (right is the mouse's right, up its forward), always
// in the same place and the same size (the scene's green marker says the
// same but can be small or hidden by the hemisphere). Two faces:
//   - a stir gauge while the autopilot stirs (issue 26: a hint a hand can
//     follow 0.2 s late): the ring to trace, drawn at the dial's size, a
//     green dot going round it at the autopilot's pace and the proxy as a
//     blue dot where it is against the ring, with the ring's size and pace
//     in words;
//   - an arrow where the proxy should go (the spot to settle over, or the
//     autopilot's next move when no ring is known), its length the distance
//     (full at kFullScale), with the distance in mm.

#include <string>

#include "game/ui/hud/WindowRects.h"

struct ImDrawList;
struct ImVec2;

namespace hemiroll::game {

class HintCompass {
 public:
  static constexpr double kFullScale = 0.01;  // [m]: a centimetre or more fills the dial

  void hide() { shown_ = false; }
  // The wanted move of the proxy, in screen directions [m]; `label` heads it.
  void show(double right, double up, const char* label = "autopilot");
  // The ring to trace: the proxy and the pace dot relative to the ring's
  // centre in screen directions [m], the ring's radius [m] and its pace
  // [rad/s], positive anticlockwise seen from above.
  void showStir(double proxyRight, double proxyUp, double paceRight, double paceUp, double radius, double rate);
  bool stirring() const { return shown_ && stir_; }
  bool shown() const { return shown_; }
  double right() const { return right_; }
  double up() const { return up_; }

  // Inside an ImGui frame; notes its window in `rects` (the HUD's, for
  // layout checks) when given.
  void draw(WindowRects* rects = nullptr) const;

 private:
  void drawStir(ImDrawList* dl, const ImVec2& centre, float radius) const;

  bool shown_ = false, stir_ = false;
  const char* label_ = "autopilot";
  double right_ = 0.0, up_ = 0.0;
  double proxyRight_ = 0.0, proxyUp_ = 0.0, ringRadius_ = 0.0, rate_ = 0.0;
};

// The move (dx, dy) on the plane [m] in screen directions for a camera whose
// screen right points along `screenRightHeading` [rad] (render::screenRightHeading).
void toScreenDirections(double dx, double dy, double screenRightHeading, double& right, double& up);

}  // namespace hemiroll::game
