#include "game/ui/screens/ReplayScreen.h"

#include <imgui.h>

#include <algorithm>

#include "engine/physics/StateKinematics.h"
#include "engine/physics/StateLayout.h"
#include "engine/platform/KeyNames.h"
#include "engine/platform/Window.h"
#include "engine/render/Camera.h"
#include "engine/render/Renderer.h"
#include "game/ui/settings/Settings.h"
#include "game/ui/hud/WrappedText.h"
#include "game/ui/screens/ScreenHost.h"
#include "game/ui/screens/ScreenLayout.h"
#include "game/ui/screens/ScreenStack.h"
#include "game/ui/view/RenderSceneBuilder.h"

namespace hemiroll::game {

ReplayScreen::ReplayScreen(ScreenHost& host, std::string levelPath, std::string replayFile)
    : Screen(host), levelPath_(std::move(levelPath)), replayFile_(std::move(replayFile)) {}

ReplayScreen::~ReplayScreen() = default;

void ReplayScreen::open() {
  try {
    level_ = script::LevelLoader().loadFile(levelPath_);
    player_ = std::make_unique<ReplayPlayer>(level_.def, levelPath_, replayFile_);
    judge_.emplace(level_.def.task);
    host_.renderer().setProps(propsOf(level_.def));  // a missing mesh was named when the level was played
  } catch (const std::exception& e) {
    error_ = e.what();
    player_.reset();
  }
  clock_ = 0.0;
  trace_.clear();
  proxyPath_.clear();
}

void ReplayScreen::enter() {
  if (player_ || !error_.empty()) return;
  open();
}

void ReplayScreen::input(const platform::InputEvent& e) {
  if (e.type != platform::InputType::KeyDown) return;
  static const std::int32_t kHome = platform::keyFromName("Home");
  if (!e.repeat && (e.key == platform::Key::Escape || e.key == platform::Key::Enter)) host_.screens().pop();
  else if (e.key == platform::Key::Up || e.code == '+' || e.code == '=') speed_ = std::min(kFastest, speed_ * 2.0);
  else if (e.key == platform::Key::Down || e.code == '-') speed_ = std::max(kSlowest, speed_ / 2.0);
  else if (e.key == platform::Key::Space && !e.repeat) paused_ = !paused_;
  else if (!e.repeat && (e.code == 'r' || (kHome != 0 && e.code == kHome))) {
    player_.reset();
    open();
  }
}

void ReplayScreen::update(double dt) {
  if (!player_) return;
  if (!paused_) clock_ += dt * speed_;
  player_->playTo(static_cast<std::uint64_t>(clock_ / player_->period()));
  const haptics::ServoSnapshot& s = player_->snapshot();
  // The judge sees the frames' ticks only: enough to know the stage whose
  // target to draw (the replay itself is the logged run, bit for bit).
  task::JudgeInput in;
  in.time = s.time;
  in.state = physics::forceStateOf(s.state);
  if (!judge_->finished()) judge_->judge(in);
  fillFromSnapshot(level_.def, s, static_cast<std::size_t>(std::max(0, judge_->stage())), scene_);
  trace_.push(s.state[physics::force_slot::u_a], s.state[physics::force_slot::v_a], s.time);
  proxyPath_.push(s.proxyPosition[0], s.proxyPosition[1], s.time);
  scene_.trace = &trace_;
  scene_.camera.mode = host_.settings().camera;
  scene_.camera.zoom = host_.settings().zoom;
  scene_.camera.yaw = host_.settings().orbitYaw;
  scene_.camera.pitch = host_.settings().orbitPitch;
  inset_.update(scene_, render::screenRightHeading(scene_.camera));
  inset_.setProxyPath(&proxyPath_);
}

void ReplayScreen::paint() {
  if (!player_) {
    beginCentredPanel("replay error", 700);
    ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "This replay cannot be played:");
    wrappedText(error_);
    if (ImGui::Button("Back  (Esc)")) host_.screens().pop();
    ImGui::End();
    return;
  }
  const platform::PixelSize d = host_.window().drawableSize();
  host_.renderer().render(scene_, d.width, d.height);
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::Begin("replay", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoNav);
  ImGui::Text("replay of %s", level_.def.name.c_str());
  ImGui::Text("%.1f / %.1f s", player_->snapshot().time, static_cast<double>(player_->ticksTotal()) * player_->period());
  ImGui::Text("speed %gx%s", speed_, paused_ ? ", paused" : "");
  if (player_->done()) ImGui::Text("the end");
  ImGui::TextDisabled("Down/Up: slower/faster");
  ImGui::TextDisabled("Space: pause, R: from the start");
  ImGui::TextDisabled("Esc: back");
  ImGui::TextColored(ImVec4(0.95f, 0.45f, 0.05f, 1), "orange: the contact's path");
  ImGui::TextColored(ImVec4(0.35f, 0.55f, 1.0f, 1), "blue: the proxy's (the hand's)");
  ImGui::End();
  inset_.draw();
}

}  // namespace hemiroll::game
