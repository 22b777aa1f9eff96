#pragma once
// The screen's warning before the mass point leaves the face (issue 26: a
// player without force feedback cannot feel the pull that throws it off):
// a red frame round the whole window that pulses, and a line of words just
// above the hemisphere (where the eye is; the HUD's panels keep clear of
// it), while game/trial's FaceExitForecast says the edge is near. It
// stays on for a moment after the forecast clears, so that a warning of a
// few frames is still seen.

namespace hemiroll::game {

class EdgePulse {
 public:
  static constexpr double kHold = 0.6;       // [s] shown this long after the last warning
  static constexpr double kPulseRate = 3.0;  // [Hz]

  // Once per frame: whether the forecast warns now, and the frame's time [s].
  void update(bool warn, double dt);
  void clear() { shownFor_ = 0.0; }
  // Where the words go: centred on x, their bottom just above y [px] (the
  // hemisphere's rect on screen: its top centre).
  void setAnchor(float x, float y) {
    anchorX_ = x;
    anchorY_ = y;
  }
  bool shown() const { return shownFor_ > 0.0; }
  // The frame's opacity now, in (0, 1] while shown, 0 otherwise.
  double strength() const;

  // Inside an ImGui frame: the frame and the words over everything.
  void draw() const;

 private:
  double shownFor_ = 0.0;  // [s] left to show
  double clock_ = 0.0;     // [s] since the warning came on: the pulse's phase
  float anchorX_ = -1.0f, anchorY_ = -1.0f;  // < 0: the top centre of the window
};

}  // namespace hemiroll::game
