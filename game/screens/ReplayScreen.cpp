#include "game/screens/ReplayScreen.h"

#include <imgui.h>

#include <cmath>

#include "engine/haptics/devices/DeviceFactory.h"
#include "engine/physics/StateLayout.h"
#include "game/app/App.h"
#include "game/play/HeadlessTrial.h"
#include "game/play/ReplayCapture.h"
#include "game/screens/ScreenLayout.h"
#include "game/view/RenderSceneBuilder.h"

namespace hemiroll::game {

ReplayScreen::ReplayScreen(App& app, std::string levelPath, std::string replayFile)
    : Screen(app), levelPath_(std::move(levelPath)), replayFile_(std::move(replayFile)) {}

ReplayScreen::~ReplayScreen() = default;

void ReplayScreen::enter() {
  if (loop_ || !error_.empty()) return;
  try {
    log_ = record::ReplayReader::load(replayFile_);
    if (log_.header.levelHash != levelFileHash(levelPath_)) {
      error_ = replayFile_ + " was recorded on another version of " + levelPath_;
      return;
    }
    level_ = script::LevelLoader().loadFile(levelPath_);
    const std::string& kind = log_.header.deviceKind;
    const std::optional<haptics::DeviceSpec> spec = haptics::DeviceFactory().specOf(kind);
    if (!spec) {
      error_ = replayFile_ + " was played with a device this program does not know: '" + kind + "'";
      return;
    }
    haptics::ServoLoopDef def = HeadlessTrial::loopDefFor(level_.def, kind);
    def.period = log_.header.dt;
    // The played device's spec: the safety layer clamps to it, as it did.
    device_ = std::make_unique<haptics::ReplayDevice>(log_.inputs, *spec);
    loop_ = std::make_unique<haptics::ServoLoop>(def, *device_);
    snapshot_.state = def.initialState;
  } catch (const std::exception& e) {
    error_ = e.what();
    loop_.reset();
  }
}

void ReplayScreen::input(const platform::InputEvent& e) {
  if (e.type == platform::InputType::KeyDown && !e.repeat &&
      (e.key == platform::Key::Escape || e.key == platform::Key::Enter))
    app_.screens().pop();
}

void ReplayScreen::update(double dt) {
  if (!loop_) return;
  clock_ += dt;
  const auto due = static_cast<std::size_t>(std::min(clock_ / log_.header.dt, static_cast<double>(log_.inputs.size())));
  for (; next_ < due; ++next_) {
    const haptics::TickInput& in = log_.inputs[next_];
    for (; nextCommand_ < log_.commands.size() && log_.commands[nextCommand_].tick == in.tick; ++nextCommand_)
      loop_->post(log_.commands[nextCommand_].command);
    loop_->tick(in.latenessNs);
  }
  loop_->latest(snapshot_);
  fillFromSnapshot(level_.def, snapshot_, 0, scene_);
  trace_.push(snapshot_.state[physics::force_slot::u_a], snapshot_.state[physics::force_slot::v_a], snapshot_.time);
  scene_.trace = &trace_;
  scene_.camera.mode = app_.settings().camera;
  scene_.camera.zoom = app_.settings().zoom;
}

void ReplayScreen::paint() {
  if (!loop_) {
    beginCentredPanel("replay error", 700);
    ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "This replay cannot be played:");
    ImGui::TextWrapped("%s", error_.c_str());
    if (ImGui::Button("Back  (Esc)")) app_.screens().pop();
    ImGui::End();
    return;
  }
  const platform::PixelSize d = app_.window().drawableSize();
  app_.renderer().render(scene_, d.width, d.height);
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::Begin("replay", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Text("replay of %s", level_.def.name.c_str());
  ImGui::Text("%.1f / %.1f s", snapshot_.time, static_cast<double>(log_.inputs.size()) * log_.header.dt);
  if (next_ >= log_.inputs.size()) ImGui::Text("the end (Esc)");
  ImGui::End();
}

}  // namespace hemiroll::game
