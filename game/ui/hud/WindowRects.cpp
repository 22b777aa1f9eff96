#include "game/ui/hud/WindowRects.h"

#include <imgui.h>

namespace hemiroll::game {

void WindowRects::noteCurrentWindow(const char* name) {
  if (count_ == rects_.size()) return;
  const ImVec2 p = ImGui::GetWindowPos(), s = ImGui::GetWindowSize();
  rects_[count_++] = WindowRect{name, p.x, p.y, s.x, s.y};
}

}  // namespace hemiroll::game
