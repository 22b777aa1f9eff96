#pragma once
// A scripted player for measurements, tests and screenshots: it clicks to
// take hold (the proxy starts on the mass point), then strokes small circles
// (radius [px] of mouse motion, one turn per period) that roll the
// hemisphere gently. Events go in through App::inject, the same path as a
// player's.

namespace hemiroll::game {

class App;

struct ScriptedMouseDef {
  double clickAt = 0.3;   // [s] after the start
  double radius = 8.0;    // [px]: 2 mm at the default 0.25 mm/px
  double period = 2.0;    // [s] per turn
};

class ScriptedMouse {
 public:
  explicit ScriptedMouse(const ScriptedMouseDef& def = {}) : def_(def) {}
  // Events for time t [s] since the script started; call once per frame.
  void step(App& app, double t);
  bool clicked() const { return clicked_; }

 private:
  ScriptedMouseDef def_;
  bool clicked_ = false;
  double lastX_ = 0.0, lastY_ = 0.0;  // where the circle's last stroke ended [px]
};

}  // namespace hemiroll::game
