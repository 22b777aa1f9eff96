#include "game/hud/HintCompass.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace hemiroll::game {

void toScreenDirections(double dx, double dy, double heading, double& right, double& up) {
  // Screen right is (cos h, sin h) on the plane; screen up (away from the
  // camera) is that turned a quarter to the left.
  right = dx * std::cos(heading) + dy * std::sin(heading);
  up = -dx * std::sin(heading) + dy * std::cos(heading);
}

void HintCompass::show(double right, double up) {
  shown_ = std::isfinite(right) && std::isfinite(up);
  right_ = shown_ ? right : 0.0;
  up_ = shown_ ? up : 0.0;
}

void HintCompass::draw(WindowRects* rects) const {
  if (!shown_) return;
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(size.x / 2, size.y - 10), ImGuiCond_Always, ImVec2(0.5f, 1));
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::Begin("hint", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoNav);
  constexpr float kSide = 110.0f;
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("dial", ImVec2(kSide, kSide));
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 c(o.x + kSide / 2, o.y + kSide / 2);
  const float radius = kSide / 2 - 4;
  const ImU32 green = IM_COL32(77, 242, 140, 255);
  dl->AddCircle(c, radius, IM_COL32(160, 160, 160, 255), 48);
  const double distance = std::hypot(right_, up_);
  const float reach = radius * static_cast<float>(std::min(1.0, distance / kFullScale));
  if (reach > 3.0f) {
    const float ux = static_cast<float>(right_ / distance), uy = static_cast<float>(-up_ / distance);  // ImGui y is down
    const ImVec2 tip(c.x + reach * ux, c.y + reach * uy);
    dl->AddLine(c, tip, green, 4.0f);
    const float head = 10.0f;
    dl->AddTriangleFilled(tip, ImVec2(tip.x - head * ux - 0.6f * head * uy, tip.y - head * uy + 0.6f * head * ux),
                          ImVec2(tip.x - head * ux + 0.6f * head * uy, tip.y - head * uy - 0.6f * head * ux), green);
  } else {
    dl->AddCircleFilled(c, 5.0f, green);  // on the autopilot's line: hold the course
  }
  ImGui::SameLine();
  ImGui::BeginGroup();
  ImGui::TextColored(ImVec4(0.3f, 0.95f, 0.55f, 1.0f), "autopilot");
  if (reach > 3.0f)
    ImGui::Text("move %.0f mm", distance * 1e3);
  else
    ImGui::Text("on its line");
  ImGui::EndGroup();
  if (rects) rects->noteCurrentWindow("hint");
  ImGui::End();
}

}  // namespace hemiroll::game
