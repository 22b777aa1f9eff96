#pragma once
// Shared look of the menu screens: one centred ImGui panel.

#include <imgui.h>

namespace hemiroll::game {

// Begins a centred, auto-height panel `width` px wide (at most the window's
// width less a margin); the caller ends it with ImGui::End(). A panel
// taller than the window is cut to it and scrolls (wheel, or its
// scrollbar), so that its last button is never out of reach.
inline void beginCentredPanel(const char* id, float width) {
  constexpr float kMargin = 10.0f;  // [px] each side
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  width = width < display.x - 2 * kMargin ? width : display.x - 2 * kMargin;
  ImGui::SetNextWindowPos(ImVec2(display.x / 2, display.y / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, display.y - 2 * kMargin));
  ImGui::Begin(id, nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
}

}  // namespace hemiroll::game
