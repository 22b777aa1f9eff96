#include "game/app/App.h"

#include <SDL.h>
#include <epoxy/gl.h>

#include <algorithm>

#include "game/app/SettingsFile.h"
#include "game/screens/TitleScreen.h"
#include "game/view/AssetsDirectory.h"

namespace hemiroll::game {

namespace {

// The back buffer as an image, rows top-down (GL's rows are bottom-up).
void readBack(int width, int height, render::Image& image) {
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  std::vector<std::uint8_t> rows(image.rgba.size());
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  const std::size_t stride = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(&rows[static_cast<std::size_t>(height - 1 - y) * stride], stride,
                &image.rgba[static_cast<std::size_t>(y) * stride]);
}

}  // namespace

App::App(const AppDef& def) : def_(def) {
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
  SDL_GL_SetSwapInterval(settings_.vsync ? 1 : 0);
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
  SDL_GL_SetSwapInterval(on ? 1 : 0);  // the window's context is current on this thread
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
  imgui_->beginFrame(size.width, size.height, drawable.width, drawable.height, dt);
  screens_.visible(painted_);
  for (Screen* s : painted_) s->paint();
  imgui_->endFrame();
  if (captureRequested_) {
    captureRequested_ = false;
    readBack(drawable.width, drawable.height, capture_);
  }
  window_->swap();
  return !quit_;
}

int App::run() {
  while (frame()) {
  }
  return 0;
}

}  // namespace hemiroll::game
