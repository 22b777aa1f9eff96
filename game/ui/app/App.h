#pragma once
// The game application: the window, the renderer, Dear ImGui, audio, the
// scores database, the settings and the screen stack, and the main loop:
//   events (window + injected) -> ImGui / top screen -> update -> paint -> swap
// One frame never waits for the servo loop (the play screen reads snapshots),
// and frames are paced (FramePacer) to what the top screen needs: the
// player's frame cap in play, kWatchFps watching the autopilot, kMenuFps in
// menus, kStillFps while paused, so
// that the servo thread keeps a core on a 2-core machine (issue 27). The
// interface grows with the window's height (uiScale()).
//
// Tests build an App on a hidden or Xvfb window and drive it frame by frame
// with inject(), the same InputEvents the window produces.

#include <memory>
#include <string>
#include <vector>

#include "engine/platform/FrameClock.h"
#include "engine/platform/FramePacer.h"
#include "engine/platform/InputEvent.h"
#include "engine/platform/Window.h"
#include "engine/render/Image.h"
#include "engine/render/Renderer.h"
#include "game/ui/settings/Settings.h"
#include "game/ui/audio/Audio.h"
#include "game/ui/hud/ImGuiLayer.h"
#include "game/ui/scores/ScoreStore.h"
#include "game/ui/screens/ScreenHost.h"
#include "game/ui/screens/ScreenStack.h"

namespace hemiroll::game {

struct AppDef {
  int width = 1280, height = 720;   // [window px]
  bool vsync = true;
  // Frames paced to what the top screen needs (FrameNeed, the frame cap):
  // the main thread sleeps out the rest. Off in the window tests, which
  // step frames as fast as they come.
  bool paceFrames = true;
  bool hidden = false;              // tests and benchmarks: no visible window
  std::string levelsDir;            // the level select lists *.lua here; "" = findLevelsDirectory()
  std::string scoresFile;           // "" = record::dataDirectory()/scores.sqlite
  std::string settingsFile;         // "" = configDirectory()/settings.json
  bool requestRealtime = true;      // SCHED_FIFO for the servo thread when permitted
  std::string deviceProfile;        // --device-profile: this run's instead of the settings' ("" = theirs)
};

class App final : public ScreenHost {
 public:
  static constexpr double kWatchFps = 30.0;  // the autopilot playing: its planner needs the CPU
  static constexpr double kMenuFps = 30.0;   // hover and clicks need no more
  static constexpr double kStillFps = 15.0;  // a paused scene does not move
  // Opens the window (throws platform::PlatformError, e.g. no display) and
  // shows the title screen.
  explicit App(const AppDef& def);
  ~App();

  // Frames until the player quits; returns the exit code (0).
  int run();
  // One frame; false once the player asked to quit.
  bool frame();
  void inject(const platform::InputEvent& event) { injected_.push_back(event); }

  // ScreenHost: what the screens may use.
  void requestQuit() override { quit_ = true; }
  ScreenStack& screens() override { return screens_; }
  platform::Window& window() override { return *window_; }
  render::Renderer& renderer() override { return *renderer_; }
  Audio& audio() override { return *audio_; }
  ScoreStore& scores() override { return *scores_; }
  Settings& settings() override { return settings_; }
  // The settings and research screens save on leaving.
  void saveSettings() override;
  void setVsync(bool on) override;
  const std::string& levelsDir() const override { return def_.levelsDir; }
  bool requestRealtime() const override { return def_.requestRealtime; }
  double fps() const override { return clock_.medianFps(); }
  // The frame rate the top screen is paced to now [frames/s] (0 = unpaced).
  double targetFps() const;
  // The interface's scale now: the setting times the window's height / 720.
  double uiScale() const;
  const platform::FramePacer& pacer() const { return pacer_; }
  // Shown on the title.
  const std::vector<std::string>& notes() const override { return notes_; }

  const char* topScreen() const { return screens_.top() ? screens_.top()->name() : ""; }
  const AppDef& def() const { return def_; }
  std::size_t frames() const { return clock_.frames(); }
  // The next frame is read back before it is shown (screenshots, tests):
  // capture() then holds it, rows top-down, at the drawable size.
  void requestCapture() { captureRequested_ = true; }
  const render::Image& capture() const { return capture_; }

 private:
  AppDef def_;
  std::unique_ptr<platform::Window> window_;
  std::unique_ptr<render::Renderer> renderer_;
  std::unique_ptr<ImGuiLayer> imgui_;
  std::unique_ptr<Audio> audio_;
  std::unique_ptr<ScoreStore> scores_;
  std::string settingsFile_;
  Settings settings_;
  ScreenStack screens_;
  platform::FrameClock clock_;
  platform::FramePacer pacer_;
  std::vector<platform::InputEvent> events_, injected_;
  std::vector<Screen*> painted_;  // this frame's visible screens (reused)
  std::vector<std::string> notes_;
  bool quit_ = false;
  bool captureRequested_ = false;
  render::Image capture_;
};

}  // namespace hemiroll::game
