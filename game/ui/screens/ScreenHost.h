#pragma once
// What a screen may use of the application that hosts it: the window, the
// renderer, sound, scores, settings and the screen stack. App implements it;
// screens see only this, so that the arrow runs one way (the app owns the
// screens, the screens do not know the app) and a screen can be driven by
// anything that offers these services.

#include <string>
#include <vector>

namespace hemiroll::platform {
class Window;
}
namespace hemiroll::render {
class Renderer;
}

namespace hemiroll::game {

class Audio;
class ScoreStore;
class ScreenStack;
struct Settings;

class ScreenHost {
 public:
  virtual ~ScreenHost() = default;

  virtual ScreenStack& screens() = 0;
  virtual platform::Window& window() = 0;
  virtual render::Renderer& renderer() = 0;
  virtual Audio& audio() = 0;
  virtual ScoreStore& scores() = 0;
  virtual Settings& settings() = 0;
  // Writes the settings to their file now; a failure becomes a note.
  virtual void saveSettings() = 0;
  virtual void setVsync(bool on) = 0;
  virtual void requestQuit() = 0;
  // Where the level select looks for levels.
  virtual const std::string& levelsDir() const = 0;
  // Whether play sessions ask for SCHED_FIFO for their servo thread.
  virtual bool requestRealtime() const = 0;
  virtual double fps() const = 0;
  // Things the player should know (audio off, scores moved aside).
  virtual const std::vector<std::string>& notes() const = 0;
};

}  // namespace hemiroll::game
