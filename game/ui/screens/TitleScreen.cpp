#include "game/ui/screens/TitleScreen.h"

#include <imgui.h>

#include "game/ui/settings/Settings.h"
#include "game/ui/hud/WrappedText.h"
#include "game/ui/screens/LevelSelectScreen.h"
#include "game/ui/screens/ResearchScreen.h"
#include "game/ui/screens/ScreenHost.h"
#include "game/ui/screens/ScreenLayout.h"
#include "game/ui/screens/ScreenStack.h"
#include "game/ui/screens/SettingsScreen.h"

namespace hemiroll::game {

void TitleScreen::play() { host_.screens().push(std::make_unique<LevelSelectScreen>(host_)); }
void TitleScreen::settings() { host_.screens().push(std::make_unique<SettingsScreen>(host_)); }
void TitleScreen::research() { host_.screens().push(std::make_unique<ResearchScreen>(host_)); }

void TitleScreen::input(const platform::InputEvent& e) {
  if (e.type != platform::InputType::KeyDown || e.repeat) return;
  if (e.key == platform::Key::Enter || e.key == platform::Key::Space) play();
  else if (e.key == platform::Key::Escape || e.code == 'q') host_.requestQuit();
  else if (e.code == 's') settings();
  else if (e.code == 'r') research();
}

void TitleScreen::paint() {
  beginCentredPanel("title", 520);
  ImGui::SetWindowFontScale(3.0f);
  ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.35f, 1.0f), "hemiroll");
  ImGui::SetWindowFontScale(1.0f);
  wrappedText("Roll the hemisphere by moving the mass point on its face. In a level, click or press " +
              host_.settings().keys.keyName(KeyAction::TakeHold) + " to take hold.");
  ImGui::Spacing();
  const ImVec2 button(-1, 0);
  if (ImGui::Button("Play  (Enter)", button)) play();
  if (ImGui::Button("Settings  (S)", button)) settings();
  if (ImGui::Button("Research session  (R)", button)) research();
  if (ImGui::Button("Quit  (Esc)", button)) host_.requestQuit();
  for (const std::string& note : host_.notes()) wrappedTextDisabled(note);
  ImGui::End();
}

}  // namespace hemiroll::game
