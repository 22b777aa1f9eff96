#include "tests/game/ui/support/StrokedTrial.h"

#include <cmath>
#include <thread>

#include "engine/record/ContentHash.h"
#include "engine/script/LevelLoader.h"
#include "game/trial/ReplayCapture.h"

namespace hemiroll::test {

using namespace std::chrono_literals;

StrokedTrial playStrokedTrial(const StrokedTrialDef& def) {
  script::LoadedLevel level = script::LevelLoader().loadFile(def.level);
  game::PlaySessionDef sessionDef;
  sessionDef.replayFile = def.replayFile;
  sessionDef.levelHash = record::fileContentHash(def.level);
  game::PlaySession session(level, sessionDef);
  session.start();
  session.click();
  const auto start = std::chrono::steady_clock::now();
  double lastX = 0.0;
  while (std::chrono::steady_clock::now() - start < def.duration) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double x = def.amplitude * std::sin(4.0 * t);
    session.pointerMotion(x - lastX, 0.0);
    lastX = x;
    session.frame();
    std::this_thread::sleep_for(10ms);
  }
  if (def.pauseAtTheEnd) {
    session.pause();
    std::this_thread::sleep_for(50ms);
  }
  session.finish();
  return {session.snapshot(), session.replayError()};
}

}  // namespace hemiroll::test
