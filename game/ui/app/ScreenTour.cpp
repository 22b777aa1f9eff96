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

}  // namespace

std::vector<ScreenTourStop> runScreenTour(App& app, const ScreenTourDef& def) {
  std::vector<ScreenTourStop> stops;
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

  ScriptedMouse mouse;
  const auto start = std::chrono::steady_clock::now();
  bool edgeTaken = !def.captureEdge;
  for (;;) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (t >= def.playSeconds) break;
    mouse.step(app, t);
    app.frame();
    const auto* play = dynamic_cast<const PlayScreen*>(app.screens().top());
    if (!edgeTaken && play != nullptr && play->pulse().shown()) {
      stop(app, stops, "edge");
      edgeTaken = true;
    }
  }
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
  if (!def.autopilot) return stops;

  // The autopilot: watched from the level select, then taken over with the
  // hint shown (the green arrow: where it would put the proxy now).
  app.inject(platform::keyDownEvent("Escape"));
  settle(app);
  app.inject(platform::keyDownEvent("A"));
  settle(app, 2);
  frameFor(app, def.playSeconds);
  stop(app, stops, "watch");
  app.inject(platform::keyDownEvent("Space"));  // take over
  app.inject(platform::keyDownEvent("H"));      // the hint
  ScriptedMouse after;
  const auto handed = std::chrono::steady_clock::now();
  for (;;) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - handed).count();
    if (t >= 2.5) break;  // long enough for the mouse's circle to part from the autopilot's plan
    after.step(app, t);
    app.frame();
  }
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
  ScriptedMouse again;
  const auto held = std::chrono::steady_clock::now();
  for (;;) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - held).count();
    if (t >= 1.5) break;
    again.step(app, t);
    app.frame();
  }
  app.inject(platform::keyDownEvent("Backspace"));
  settle(app, 4);
  stop(app, stops, "letgo");
  return stops;
}

}  // namespace hemiroll::game
