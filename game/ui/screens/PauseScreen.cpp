#include "game/ui/screens/PauseScreen.h"

#include <imgui.h>

#include "game/ui/hud/WrappedText.h"
#include "game/ui/screens/PlayScreen.h"
#include "game/ui/screens/ScreenHost.h"
#include "game/ui/screens/ScreenLayout.h"
#include "game/ui/screens/ScreenStack.h"

namespace hemiroll::game {

void PauseScreen::resume() {
  play_.resume();
  host_.screens().pop();
}

void PauseScreen::restart() {
  play_.restart();
  host_.screens().pop();
}

void PauseScreen::watch() {
  play_.watchAutopilot();
  host_.screens().pop();
}

void PauseScreen::quit() {
  play_.quit();  // the play screen sees the finished trial on its next update
  host_.screens().pop();
}

void PauseScreen::input(const platform::InputEvent& e) {
  if (e.type != platform::InputType::KeyDown || e.repeat) return;
  if (e.key == platform::Key::Escape || e.key == platform::Key::Enter) resume();
  else if (e.code == 'r') restart();
  else if (e.code == 'q') quit();
  else if (e.code == 'a' && play_.restartAllowed()) watch();
}

// The paused loop still publishes a row per tick (time standing still): the
// play screen keeps draining them, or the ring would fill in 4 s.
void PauseScreen::update(double) { play_.drainWhilePaused(); }

// Beside the scene, not over it: after a safety stop the player looks at
// the hemisphere to see where it stopped.
void PauseScreen::paint() {
  beginSidePanel("pause", 460);
  ImGui::SetWindowFontScale(1.6f);
  ImGui::Text("Paused");
  ImGui::SetWindowFontScale(1.0f);
  if (!reason_.empty()) wrappedText(ImVec4(0.95f, 0.75f, 0.3f, 1), reason_);
  const ImVec2 button(-1, 0);
  if (ImGui::Button("Continue  (Esc)", button)) resume();
  // A research session's trial is recorded once: it cannot be restarted.
  if (play_.restartAllowed() && ImGui::Button("Restart  (R)", button)) restart();
  if (play_.restartAllowed() && ImGui::Button("Watch the autopilot  (A)", button)) watch();
  if (ImGui::Button("Quit the trial  (Q)", button)) quit();
  ImGui::End();
}

}  // namespace hemiroll::game
