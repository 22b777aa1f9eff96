#include "game/ui/app/ScreenTour.h"

#include <algorithm>
#include <chrono>

#include "engine/platform/KeyNames.h"
#include "game/ui/app/App.h"
#include "game/ui/app/ScriptedMouse.h"
#include "game/ui/screens/LevelSelectScreen.h"
#include "game/ui/screens/PlayScreen.h"

namespace hemiroll::game {

namespace {

// A few frames let the stack change and the new screen draw itself.
void settle(App& app, int frames = 3) {
  for (int i = 0; i < frames; ++i) app.frame();
}

// `name`: the picture's name when it is not the screen's own.
void stop(App& app, std::vector<ScreenTourStop>& out, const std::string& name = "") {
  app.requestCapture();
  app.frame();
  out.push_back({name.empty() ? app.topScreen() : name, app.capture()});
}

void frameFor(App& app, double seconds) {
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds) app.frame();
}

// A fresh scripted mouse stroking for that long (from its own start), a
// frame after each step.
// With edgeStops, the first frame that shows the edge warning is also kept
// (as "edge"): it comes only when the scripted mouse happens to cause a fall.
void strokeFor(App& app, double seconds, std::vector<ScreenTourStop>* edgeStops = nullptr) {
  ScriptedMouse mouse;
  const auto start = std::chrono::steady_clock::now();
  bool edgeTaken = edgeStops == nullptr;
  for (;;) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (t >= seconds) break;
    mouse.step(app, t);
    app.frame();
    const auto* play = dynamic_cast<const PlayScreen*>(app.screens().top());
    if (!edgeTaken && play != nullptr && play->pulse().shown()) {
      stop(app, *edgeStops, "edge");
      edgeTaken = true;
    }
  }
}

// Title, settings and the level select, then def.level started.
void tourMenus(App& app, const ScreenTourDef& def, std::vector<ScreenTourStop>& stops) {
  settle(app);
  stop(app, stops);  // title

  app.inject(platform::keyDownEvent("S"));
  settle(app);
  stop(app, stops);  // settings
  app.inject(platform::keyDownEvent("Escape"));
  settle(app);

  app.inject(platform::keyDownEvent("Return"));
  settle(app);
  stop(app, stops);  // level select

  // Down until the wanted level is selected (at most once round the list).
  if (auto* select = dynamic_cast<LevelSelectScreen*>(app.screens().top())) {
    for (std::size_t i = 0; i < select->entries().size(); ++i) {
      if (select->entries()[static_cast<std::size_t>(select->selected())].path == def.level) break;
      app.inject(platform::keyDownEvent("Down"));
      app.frame();
    }
  }
  app.inject(platform::keyDownEvent("Return"));
  settle(app, 2);
}

// The trial played by the mouse, paused, quit to its results, and its
// replay; back on the results screen.
void tourTrial(App& app, const ScreenTourDef& def, std::vector<ScreenTourStop>& stops) {
  strokeFor(app, def.playSeconds, def.captureEdge ? &stops : nullptr);
  stop(app, stops);  // play

  app.inject(platform::keyDownEvent("Escape"));
  settle(app);
  stop(app, stops);  // pause

  app.inject(platform::keyDownEvent("Q"));
  settle(app);
  stop(app, stops);  // results

  // The trial's replay, slowed down, with the magnified floor and the paths.
  app.inject(platform::keyDownEvent("W"));
  settle(app);
  app.inject(platform::keyDownEvent("Down"));  // half speed
  frameFor(app, std::min(def.playSeconds, 2.0));
  stop(app, stops);  // replay
  app.inject(platform::keyDownEvent("Escape"));
  settle(app);
}

// The autopilot: watched from the level select, then taken over with the
// hint shown (the green arrow: where it would put the proxy now); then the
// level played again, and let go.
void tourAutopilot(App& app, const ScreenTourDef& def, std::vector<ScreenTourStop>& stops) {
  app.inject(platform::keyDownEvent("Escape"));
  settle(app);
  app.inject(platform::keyDownEvent("A"));
  settle(app, 2);
  frameFor(app, def.playSeconds);
  stop(app, stops, "watch");
  app.inject(platform::keyDownEvent("Space"));  // take over
  app.inject(platform::keyDownEvent("H"));      // the hint
  strokeFor(app, 2.5);  // long enough for the mouse's circle to part from the autopilot's plan
  stop(app, stops, "hint");

  // Playing again: the trial waits for the take-hold, and says so.
  app.inject(platform::keyDownEvent("Escape"));
  settle(app);
  app.inject(platform::keyDownEvent("Q"));
  settle(app);
  app.inject(platform::keyDownEvent("Return"));
  settle(app, 4);
  stop(app, stops, "start");

  // Letting go: the physics waits, and the screen says how to go on.
  strokeFor(app, 1.5);
  app.inject(platform::keyDownEvent("Backspace"));
  settle(app, 4);
  stop(app, stops, "letgo");
}

}  // namespace

std::vector<ScreenTourStop> runScreenTour(App& app, const ScreenTourDef& def) {
  std::vector<ScreenTourStop> stops;
  tourMenus(app, def, stops);
  tourTrial(app, def, stops);
  if (def.autopilot) tourAutopilot(app, def, stops);
  return stops;
}

}  // namespace hemiroll::game
