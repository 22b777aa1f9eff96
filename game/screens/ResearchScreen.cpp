#include "game/screens/ResearchScreen.h"

#include <imgui.h>

#include <algorithm>
#include <cstring>

#include "game/app/App.h"
#include "game/screens/ScreenLayout.h"

namespace hemiroll::game {

void ResearchScreen::enter() {
  const std::string& p = app_.settings().participant;
  participant_.fill('\0');
  std::copy_n(p.begin(), std::min(p.size(), participant_.size() - 1), participant_.begin());
}

void ResearchScreen::leave() { app_.saveSettings(); }

void ResearchScreen::input(const platform::InputEvent& e) {
  if (e.type == platform::InputType::KeyDown && e.key == platform::Key::Escape && !e.repeat) app_.screens().pop();
}

void ResearchScreen::paint() {
  Settings& s = app_.settings();
  beginCentredPanel("research", 700);
  ImGui::SetWindowFontScale(1.6f);
  ImGui::Text("Research session");
  ImGui::SetWindowFontScale(1.0f);
  if (ImGui::InputText("participant id", participant_.data(), participant_.size())) {
    // Ids name folders: letters, digits, '-' and '_' only.
    std::string id;
    for (char c : std::string(participant_.data()))
      if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') id += c;
    s.participant = id.empty() ? "player" : id;
  }
  ImGui::Text("trials are stored as participant '%s'", s.participant.c_str());
  ImGui::Text("scores: %s", app_.scores().file().c_str());
  ImGui::Text("data directory: %s", dataDirectory().c_str());
  ImGui::TextDisabled("(set HEMIROLL_DATA_DIR or XDG_DATA_HOME to change it)");
  if (ImGui::Button("Back  (Esc)", ImVec2(-1, 0))) app_.screens().pop();
  ImGui::End();
}

}  // namespace hemiroll::game
