#include "game/screens/ReplayScreen.h"

#include <imgui.h>

#include "engine/physics/StateLayout.h"
#include "engine/platform/Window.h"
#include "engine/render/Renderer.h"
#include "game/app/Settings.h"
#include "game/screens/ScreenHost.h"
#include "game/screens/ScreenLayout.h"
#include "game/screens/ScreenStack.h"
#include "game/view/RenderSceneBuilder.h"

namespace hemiroll::game {

ReplayScreen::ReplayScreen(ScreenHost& host, std::string levelPath, std::string replayFile)
    : Screen(host), levelPath_(std::move(levelPath)), replayFile_(std::move(replayFile)) {}

ReplayScreen::~ReplayScreen() = default;

void ReplayScreen::enter() {
  if (player_ || !error_.empty()) return;
  try {
    level_ = script::LevelLoader().loadFile(levelPath_);
    player_ = std::make_unique<ReplayPlayer>(level_.def, levelPath_, replayFile_);
    host_.renderer().setProps(propsOf(level_.def));  // a missing mesh was named when the level was played
  } catch (const std::exception& e) {
    error_ = e.what();
    player_.reset();
  }
}

void ReplayScreen::input(const platform::InputEvent& e) {
  if (e.type == platform::InputType::KeyDown && !e.repeat &&
      (e.key == platform::Key::Escape || e.key == platform::Key::Enter))
    host_.screens().pop();
}

void ReplayScreen::update(double dt) {
  if (!player_) return;
  clock_ += dt;
  player_->playTo(static_cast<std::uint64_t>(clock_ / player_->period()));
  const haptics::ServoSnapshot& s = player_->snapshot();
  fillFromSnapshot(level_.def, s, 0, scene_);
  trace_.push(s.state[physics::force_slot::u_a], s.state[physics::force_slot::v_a], s.time);
  scene_.trace = &trace_;
  scene_.camera.mode = host_.settings().camera;
  scene_.camera.zoom = host_.settings().zoom;
}

void ReplayScreen::paint() {
  if (!player_) {
    beginCentredPanel("replay error", 700);
    ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "This replay cannot be played:");
    ImGui::TextWrapped("%s", error_.c_str());
    if (ImGui::Button("Back  (Esc)")) host_.screens().pop();
    ImGui::End();
    return;
  }
  const platform::PixelSize d = host_.window().drawableSize();
  host_.renderer().render(scene_, d.width, d.height);
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::Begin("replay", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Text("replay of %s", level_.def.name.c_str());
  ImGui::Text("%.1f / %.1f s", player_->snapshot().time, static_cast<double>(player_->ticksTotal()) * player_->period());
  if (player_->done()) ImGui::Text("the end (Esc)");
  ImGui::End();
}

}  // namespace hemiroll::game
