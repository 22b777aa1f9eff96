#include "tests/game/ui/support/LayoutAudit.h"

#include <imgui.h>
#include <imgui_internal.h>

namespace hemiroll::test {

namespace {

// The windows a player sees: drawn this frame, top-level (ImGui's implicit
// "Debug" window is never shown unless used).
bool shown(const ImGuiWindow* w) {
  return w->Active && !w->Hidden && !(w->Flags & (ImGuiWindowFlags_ChildWindow | ImGuiWindowFlags_Tooltip)) &&
         std::string(w->Name).rfind("Debug##", 0) != 0;
}

std::string rect(const ImGuiWindow* w) {
  return std::to_string(int(w->Pos.x)) + "," + std::to_string(int(w->Pos.y)) + " " + std::to_string(int(w->Size.x)) +
         "x" + std::to_string(int(w->Size.y));
}

}  // namespace

std::vector<std::string> layoutProblems(float displayWidth, float displayHeight, const game::WindowRect* keepClear) {
  std::vector<std::string> problems;
  constexpr float kSlack = 0.5f;  // [px] ImGui's float rounding
  for (const ImGuiWindow* w : GImGui->Windows) {
    if (!shown(w)) continue;
    const std::string name = std::string("'") + w->Name + "' at " + rect(w);
    if (w->Pos.x < -kSlack || w->Pos.y < -kSlack || w->Pos.x + w->Size.x > displayWidth + kSlack ||
        w->Pos.y + w->Size.y > displayHeight + kSlack)
      problems.push_back(name + " is not inside the " + std::to_string(int(displayWidth)) + "x" +
                         std::to_string(int(displayHeight)) + " window");
    // This frame's content (ImGui's ContentSize is the frame before's).
    const float wide = w->DC.CursorMaxPos.x - w->DC.CursorStartPos.x, high = w->DC.CursorMaxPos.y - w->DC.CursorStartPos.y;
    const float room = w->ContentRegionRect.GetWidth(), tall = w->ContentRegionRect.GetHeight();
    if (wide > room + kSlack)
      problems.push_back(name + " cuts its text: content " + std::to_string(int(wide)) + " px wide in " +
                         std::to_string(int(room)) + " px");
    if (high > tall + kSlack && !w->ScrollbarY)
      problems.push_back(name + " cuts its text: content " + std::to_string(int(high)) + " px tall in " +
                         std::to_string(int(tall)) + " px, no scrollbar");
    if (keepClear && keepClear->width > 0.0f) {
      const game::WindowRect r{w->Name, w->Pos.x, w->Pos.y, w->Size.x, w->Size.y};
      if (r.overlaps(*keepClear))
        problems.push_back(name + " covers the hemisphere at " + std::to_string(int(keepClear->x)) + "," +
                           std::to_string(int(keepClear->y)) + " " + std::to_string(int(keepClear->width)) + "x" +
                           std::to_string(int(keepClear->height)));
    }
  }
  return problems;
}

std::vector<std::string> drawnWindows() {
  std::vector<std::string> names;
  for (const ImGuiWindow* w : GImGui->Windows)
    if (shown(w)) names.push_back(w->Name);
  return names;
}

}  // namespace hemiroll::test
