#pragma once
// Drives the game through its main screens with synthetic input, the way a
// player would: title -> (S) settings -> (Escape) title -> (Enter) level
// select -> (Down.., Enter) play, with
// a ScriptedMouse taking hold for a while -> (Escape) pause -> (Q) results
// -> (W, Down) the replay at half speed -> (Escape) results.
// One frame is captured at each stop. Used by the screen tests and by
// `hemiroll play --tour DIR` (the README's screenshots).

#include <string>
#include <vector>

#include "engine/render/Image.h"

namespace hemiroll::game {

class App;

struct ScreenTourDef {
  std::string level;        // path of the level to pick, as the level select lists it
  double playSeconds = 2.0; // [s] of wall time played by the scripted mouse
  // After results: back to the level select, watch the autopilot ("watch"),
  // take over with the hint on ("hint"), quit and play again: the trial
  // waiting for the take-hold ("start"); take hold, play, let go: the
  // physics waits and says how to go on ("letgo").
  bool autopilot = true;
  // While the scripted mouse plays: the first frame with the edge warning on
  // (the pulse before the mass point leaves the face), as "edge", when one
  // comes (`hemiroll play --tour`; off for the tests, whose stops are fixed).
  bool captureEdge = false;
};

struct ScreenTourStop {
  std::string screen;       // App::topScreen() when the frame was captured
  render::Image image;
};

std::vector<ScreenTourStop> runScreenTour(App& app, const ScreenTourDef& def);

}  // namespace hemiroll::game
