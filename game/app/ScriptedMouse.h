#pragma once
// A scripted player for measurements, tests and screenshots: it moves the
// pointer onto the mass point (the window's centre, where the pointer
// mapping puts the device origin and a level's mass point starts), clicks to
// take hold, then draws small circles (radius [px], one turn per period)
// that roll the hemisphere gently. Events go in through App::inject, the
// same path as a player's.

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
};

}  // namespace hemiroll::game
