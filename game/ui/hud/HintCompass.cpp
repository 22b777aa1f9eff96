#include "game/ui/hud/HintCompass.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace hemiroll::game {

void toScreenDirections(double dx, double dy, double heading, double& right, double& up) {
  // Screen right is (cos h, sin h) on the plane; screen up (away from the
  // camera) is that turned a quarter to the left.
  right = dx * std::cos(heading) + dy * std::sin(heading);
  up = -dx * std::sin(heading) + dy * std::cos(heading);
}

void HintCompass::show(double right, double up, const char* label) {
  shown_ = std::isfinite(right) && std::isfinite(up);
  stir_ = false;
  label_ = label;
  right_ = shown_ ? right : 0.0;
  up_ = shown_ ? up : 0.0;
}

void HintCompass::showStir(double proxyRight, double proxyUp, double paceRight, double paceUp, double radius,
                           double rate) {
  shown_ = std::isfinite(proxyRight) && std::isfinite(proxyUp) && std::isfinite(paceRight) && std::isfinite(paceUp) &&
           std::isfinite(radius) && radius > 0.0 && std::isfinite(rate) && rate != 0.0;
  stir_ = shown_;
  label_ = "circle";
  proxyRight_ = shown_ ? proxyRight : 0.0;
  proxyUp_ = shown_ ? proxyUp : 0.0;
  right_ = shown_ ? paceRight : 0.0;
  up_ = shown_ ? paceUp : 0.0;
  ringRadius_ = shown_ ? radius : 0.0;
  rate_ = shown_ ? rate : 0.0;
}

void HintCompass::drawStir(ImDrawList* dl, const ImVec2& c, float radius) const {
  // The ring at 0.6 of the dial; the proxy on the same scale, kept inside.
  const float ring = 0.6f * radius;
  const double scale = ring / ringRadius_;  // [px/m]
  const ImU32 green = IM_COL32(77, 242, 140, 255), blue = IM_COL32(90, 150, 255, 255);
  dl->AddCircle(c, ring, IM_COL32(77, 242, 140, 160), 48, 2.0f);
  const ImVec2 pace(c.x + static_cast<float>(scale * right_), c.y - static_cast<float>(scale * up_));
  dl->AddCircleFilled(pace, 7.0f, green);
  double px = scale * proxyRight_, py = scale * proxyUp_;
  const double far = std::hypot(px, py), edge = radius - 6.0;
  if (far > edge) {
    px *= edge / far;
    py *= edge / far;
  }
  dl->AddCircleFilled(ImVec2(c.x + static_cast<float>(px), c.y - static_cast<float>(py)), 5.0f, blue);
  dl->AddCircleFilled(c, 2.0f, IM_COL32(160, 160, 160, 255));
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
  if (stir_) {
    drawStir(dl, c, radius);
    ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::TextColored(ImVec4(0.3f, 0.95f, 0.55f, 1.0f), "circle: follow the green dot");
    const double across = 2.0 * ringRadius_ * 1e3;  // [mm]
    ImGui::Text(across < 10.0 ? "%.1f mm circles," : "%.0f mm circles,", across);
    ImGui::Text("a turn every %.1f s,", 2.0 * M_PI / std::abs(rate_));
    ImGui::Text("%s", rate_ > 0.0 ? "anticlockwise" : "clockwise");
    ImGui::EndGroup();
    if (rects) rects->noteCurrentWindow("hint");
    ImGui::End();
    return;
  }
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
  ImGui::TextColored(ImVec4(0.3f, 0.95f, 0.55f, 1.0f), "%s", label_);
  if (reach > 3.0f)
    ImGui::Text("move %.0f mm", distance * 1e3);
  else
    ImGui::Text("%s", std::string(label_) == "settle" ? "hold still here" : "on its line");
  ImGui::EndGroup();
  if (rects) rects->noteCurrentWindow("hint");
  ImGui::End();
}

}  // namespace hemiroll::game
