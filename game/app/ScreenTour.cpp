#include "game/app/ScreenTour.h"

#include <chrono>

#include "game/app/App.h"
#include "game/app/ScriptedMouse.h"
#include "game/screens/LevelSelectScreen.h"

namespace hemiroll::game {

namespace {

platform::InputEvent keyEvent(platform::Key key, int code = 0) {
  platform::InputEvent e;
  e.type = platform::InputType::KeyDown;
  e.key = key;
  e.code = code;
  return e;
}

// A few frames let the stack change and the new screen draw itself.
void settle(App& app, int frames = 3) {
  for (int i = 0; i < frames; ++i) app.frame();
}

void stop(App& app, std::vector<ScreenTourStop>& out) {
  app.requestCapture();
  app.frame();
  out.push_back({app.topScreen(), app.capture()});
}

}  // namespace

std::vector<ScreenTourStop> runScreenTour(App& app, const ScreenTourDef& def) {
  std::vector<ScreenTourStop> stops;
  settle(app);
  stop(app, stops);  // title

  app.inject(keyEvent(platform::Key::Other, 's'));
  settle(app);
  stop(app, stops);  // settings
  app.inject(keyEvent(platform::Key::Escape));
  settle(app);

  app.inject(keyEvent(platform::Key::Enter));
  settle(app);
  stop(app, stops);  // level select

  // Down until the wanted level is selected (at most once round the list).
  if (auto* select = dynamic_cast<LevelSelectScreen*>(app.screens().top())) {
    for (std::size_t i = 0; i < select->entries().size(); ++i) {
      if (select->entries()[static_cast<std::size_t>(select->selected())].path == def.level) break;
      app.inject(keyEvent(platform::Key::Down));
      app.frame();
    }
  }
  app.inject(keyEvent(platform::Key::Enter));
  settle(app, 2);

  ScriptedMouse mouse;
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (t >= def.playSeconds) break;
    mouse.step(app, t);
    app.frame();
  }
  stop(app, stops);  // play

  app.inject(keyEvent(platform::Key::Escape));
  settle(app);
  stop(app, stops);  // pause

  app.inject(keyEvent(platform::Key::Other, 'q'));
  settle(app);
  stop(app, stops);  // results
  return stops;
}

}  // namespace hemiroll::game
