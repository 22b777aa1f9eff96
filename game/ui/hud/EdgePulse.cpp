#include "game/ui/hud/EdgePulse.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "game/ui/hud/ImGuiLayer.h"

namespace hemiroll::game {

void EdgePulse::update(bool warn, double dt) {
  const double step = std::isfinite(dt) && dt > 0.0 ? dt : 0.0;
  if (warn) {
    if (!shown()) clock_ = 0.0;
    shownFor_ = kHold;
  } else {
    shownFor_ = std::max(0.0, shownFor_ - step);
  }
  clock_ += step;
}

// Starts at full (the first frame is the most urgent), then pulses between
// half and full.
double EdgePulse::strength() const {
  if (!shown()) return 0.0;
  return 0.75 + 0.25 * std::cos(2.0 * std::numbers::pi * kPulseRate * clock_);
}

void EdgePulse::draw() const {
  if (!shown()) return;
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  const float scale = uiScale();
  const float band = 22.0f * scale;
  const int alpha = static_cast<int>(std::lround(200.0 * strength()));
  const ImU32 solid = IM_COL32(235, 40, 30, alpha), clear = IM_COL32(235, 40, 30, 0);
  // Each edge a band fading inwards: the eye catches it at the side of
  // the view without the band covering the scene.
  dl->AddRectFilledMultiColor(ImVec2(0, 0), ImVec2(size.x, band), solid, solid, clear, clear);
  dl->AddRectFilledMultiColor(ImVec2(0, size.y - band), ImVec2(size.x, size.y), clear, clear, solid, solid);
  dl->AddRectFilledMultiColor(ImVec2(0, 0), ImVec2(band, size.y), solid, clear, clear, solid);
  dl->AddRectFilledMultiColor(ImVec2(size.x - band, 0), ImVec2(size.x, size.y), clear, solid, solid, clear);
  const char* words = "Sliding off the face: ease off!";
  const ImVec2 text = ImGui::CalcTextSize(words);
  const float centre = anchorX_ >= 0.0f ? anchorX_ : size.x * 0.5f;
  const float bottom = anchorY_ >= 0.0f ? anchorY_ - 12.0f * scale : band + text.y + 12.0f * scale;
  const ImVec2 at(std::clamp(centre - text.x * 0.5f, band, std::max(band, size.x - band - text.x)),
                  std::max(band + 6.0f * scale, bottom - text.y));
  dl->AddRectFilled(ImVec2(at.x - 10 * scale, at.y - 5 * scale), ImVec2(at.x + text.x + 10 * scale, at.y + text.y + 5 * scale),
                    IM_COL32(120, 10, 10, std::min(230, alpha + 30)), 6.0f * scale);
  dl->AddText(at, IM_COL32(255, 240, 230, 255), words);
}

}  // namespace hemiroll::game
