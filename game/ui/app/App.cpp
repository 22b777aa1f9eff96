#include "game/ui/app/App.h"

#include <epoxy/gl.h>

#include <algorithm>

#include "engine/render/Framebuffer.h"
#include "game/ui/settings/SettingsFile.h"
#include "game/ui/screens/TitleScreen.h"
#include "game/ui/view/ShippedDirectories.h"

namespace hemiroll::game {

App::App(const AppDef& def) : def_(def) {
  if (def_.levelsDir.empty()) def_.levelsDir = findLevelsDirectory();
  platform::WindowDef w;
  w.title = "hemiroll";
  w.width = def.width;
  w.height = def.height;
  w.vsync = def.vsync;
  w.hidden = def.hidden;
  window_ = platform::Window::create(w);
  settingsFile_ = def.settingsFile.empty() ? (configDirectory() / "settings.json").string() : def.settingsFile;
  LoadedSettings loaded = loadSettings(settingsFile_);
  settings_ = loaded.settings;
  for (const std::string& n : loaded.notes) notes_.push_back(n);
  // --no-vsync (measuring) wins over the saved choice for this run.
  settings_.vsync = settings_.vsync && def.vsync;
  if (!def.deviceProfile.empty()) settings_.deviceProfile = def.deviceProfile;
  window_->setVsync(settings_.vsync);
  render::RendererDef r;
  r.assetsDir = findAssetsDirectory();
  if (r.assetsDir.empty()) r.assetsDir = "assets";
  renderer_ = std::make_unique<render::Renderer>(r);
  for (const std::string& n : renderer_->notes()) notes_.push_back(n);
  imgui_ = std::make_unique<ImGuiLayer>();
  AudioDef a;
  a.volume = settings_.volume;
  audio_ = std::make_unique<Audio>(a);
  if (!audio_->available()) notes_.push_back(audio_->note());
  scores_ = std::make_unique<ScoreStore>(def.scoresFile);
  for (const std::string& n : scores_->notes()) notes_.push_back(n);
  screens_.push(std::make_unique<TitleScreen>(*this));
  screens_.apply();
}

App::~App() {
  // Screens first: the play screen stops its servo thread and frees GL objects
  // while the context and the audio device still exist.
  screens_.reset(nullptr);
  screens_.apply();
}

void App::saveSettings() {
  const std::string error = game::saveSettings(settingsFile_, settings_);
  if (!error.empty() && std::find(notes_.begin(), notes_.end(), error) == notes_.end()) notes_.push_back(error);
}

void App::setVsync(bool on) {
  settings_.vsync = on;
  window_->setVsync(on);
}

double App::targetFps() const {
  if (!def_.paceFrames) return 0.0;
  const double cap = std::clamp(settings_.frameCap, kFrameCapFps[0], kFrameCapFps[1]);
  switch (screens_.top() ? screens_.top()->frameNeed() : FrameNeed::Menu) {
    case FrameNeed::Play: return cap;
    case FrameNeed::Watch: return std::min(cap, kWatchFps);
    case FrameNeed::Menu: return std::min(cap, kMenuFps);
    case FrameNeed::Still: return std::min(cap, kStillFps);
  }
  return cap;
}

// Laid out for 720 lines; a 1080-line window gets half as much again, so
// that text and dials keep their size on the screen, not in pixels.
double App::uiScale() const {
  constexpr double kDesignHeight = 720.0;
  const double window = std::clamp(window_->windowSize().height / kDesignHeight, 0.75, 3.0);
  return std::clamp(settings_.uiScale, kUiScale[0], kUiScale[1]) * window;
}

bool App::frame() {
  screens_.apply();
  if (screens_.empty()) quit_ = true;
  if (quit_) return false;
  events_.clear();
  window_->pollEvents(events_);
  events_.insert(events_.end(), injected_.begin(), injected_.end());
  injected_.clear();
  for (const platform::InputEvent& e : events_) {
    if (e.type == platform::InputType::Quit) quit_ = true;
    const bool taken = imgui_->feed(e);
    // The play screen follows the pointer even over the HUD; clicks and the
    // wheel on an ImGui window are the window's.
    const bool button = e.type == platform::InputType::ButtonDown || e.type == platform::InputType::ButtonUp ||
                        e.type == platform::InputType::Wheel;
    if (!(taken && button) && screens_.top()) screens_.top()->input(e);
  }
  const double dt = clock_.tick();
  if (screens_.top()) screens_.top()->update(dt);

  const platform::PixelSize size = window_->windowSize();
  const platform::PixelSize drawable = window_->drawableSize();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, drawable.width, drawable.height);
  glClearColor(0.09f, 0.1f, 0.13f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  imgui_->setScale(uiScale());
  imgui_->beginFrame(size.width, size.height, drawable.width, drawable.height, dt);
  screens_.visible(painted_);
  for (Screen* s : painted_) s->paint();
  imgui_->endFrame();
  if (captureRequested_) {
    captureRequested_ = false;
    capture_ = render::Framebuffer::readBackBuffer(drawable.width, drawable.height);
  }
  window_->swap();
  pacer_.pace(targetFps());
  return !quit_;
}

int App::run() {
  while (frame()) {
  }
  return 0;
}

}  // namespace hemiroll::game
