#pragma once
// Shared look of the menu screens: one centred ImGui panel.

#include <imgui.h>

namespace hemiroll::game {

// Begins a centred, auto-height panel `width` px wide; the caller ends it
// with ImGui::End().
inline void beginCentredPanel(const char* id, float width) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x / 2, display.y / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(width, 0), ImGuiCond_Always);
  ImGui::Begin(id, nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
}

}  // namespace hemiroll::game
