#pragma once
// Shared look of the menu screens: one centred ImGui panel, or one beside
// the scene. Widths are designed at interface scale 1 and grow with it.

#include <imgui.h>

#include <algorithm>

#include "game/ui/hud/ImGuiLayer.h"

namespace hemiroll::game {

// Begins a centred, auto-height panel `width` px wide (at most the window's
// width less a margin); the caller ends it with ImGui::End(). A panel
// taller than the window is cut to it and scrolls (wheel, or its
// scrollbar), so that its last button is never out of reach.
inline void beginCentredPanel(const char* id, float width) {
  constexpr float kMargin = 10.0f;  // [px] each side
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  width *= uiScale();  // grows with the interface
  width = width < display.x - 2 * kMargin ? width : display.x - 2 * kMargin;
  ImGui::SetNextWindowPos(ImVec2(display.x / 2, display.y / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, display.y - 2 * kMargin));
  ImGui::Begin(id, nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
}

// Begins a panel `width` px wide (times the interface scale; at most what
// the window leaves right of its middle fifth, where the hemisphere stands)
// at the window's right edge, vertically centred, auto-height and
// scrolling when taller than the window: a menu beside the scene (pause,
// results) that leaves the hemisphere in view. The caller ends it.
inline void beginSidePanel(const char* id, float width) {
  constexpr float kMargin = 10.0f;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float scale = uiScale();
  const float room = display.x * 0.6f - 2 * kMargin;         // right of the middle fifth: x > 0.4 w
  width = std::max(std::min(width * scale, room), std::min(300.0f * scale, display.x - 2 * kMargin));
  ImGui::SetNextWindowPos(ImVec2(display.x - kMargin, display.y / 2), ImGuiCond_Always, ImVec2(1.0f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, display.y - 2 * kMargin));
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin(id, nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
}

}  // namespace hemiroll::game
