#include "game/ui/hud/FloorInset.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "engine/render/ContactTrace.h"
#include "game/ui/hud/HintCompass.h"
#include "game/ui/hud/ImGuiLayer.h"

namespace hemiroll::game {

namespace {

constexpr float kSide = 170.0f;     // [px] the map's square at interface scale 1
constexpr double kMargin = 1.25;    // the farthest thing needed sits within 1/1.25 of the half side
constexpr double kFreeBand = 1.0;   // [m] wider than this: a free component, not a size to fit

ImU32 colour(float r, float g, float b, float a = 1.0f) { return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, a)); }

}  // namespace

std::size_t insetSpanIndex(std::size_t current, double needed) {
  const auto& spans = FloorInset::kSpans;
  if (!std::isfinite(needed)) return current;
  const double want = needed * kMargin;
  std::size_t i = std::min(current, spans.size() - 1);
  while (i + 1 < spans.size() && spans[i] < want) ++i;
  while (i > 0 && want < 0.8 * spans[i - 1]) --i;
  return i;
}

void FloorInset::update(const render::RenderScene& scene, double screenRightHeading) {
  scene_ = &scene;
  heading_ = screenRightHeading;
  const double cx = scene.centre[0], cy = scene.centre[1];
  double needed = 0.0;
  for (const render::TargetMarker& t : scene.targets) {
    // A judged component's band edge, a free one's position is not a place.
    const double dx = t.halfWidth[0] < kFreeBand ? std::abs(t.position[0] - cx) + t.halfWidth[0] : 0.0;
    const double dy = t.halfWidth[1] < kFreeBand ? std::abs(t.position[1] - cy) + t.halfWidth[1] : 0.0;
    needed = std::max({needed, dx, dy});
  }
  for (const render::ZoneMarker& z : scene.forbidden) {
    // A zone close by is part of the way there; one far off is not.
    const double d = z.circle ? std::hypot(z.centre[0] - cx, z.centre[1] - cy) + z.radius
                              : std::max(std::abs(z.max[0] - cx), std::abs(z.max[1] - cy));
    if (d < 2.0 * std::max(needed, kSpans[0])) needed = std::max(needed, d);
  }
  spanIndex_ = insetSpanIndex(fitted_ ? spanIndex_ : 0, needed);
  fitted_ = true;
}

void FloorInset::draw(WindowRects* rects) const {
  if (!scene_) return;
  const render::RenderScene& s = *scene_;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(10, display.y - 10), ImGuiCond_Always, ImVec2(0, 1));
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::Begin("floor inset", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoNav |
                   ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoFocusOnAppearing);
  const float scale = uiScale();
  const float side = kSide * scale;
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(side, side));
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(o, ImVec2(o.x + side, o.y + side), true);
  dl->AddRectFilled(o, ImVec2(o.x + side, o.y + side), colour(0.84f, 0.83f, 0.80f));
  const double span = kSpans[spanIndex_];
  const float pxPerMetre = static_cast<float>(side / 2 / span);
  const ImVec2 c(o.x + side / 2, o.y + side / 2);
  // Plane point -> map pixel: about the contact point, turned like the camera.
  const auto at = [&](double x, double y) {
    double right = 0.0, up = 0.0;
    toScreenDirections(x - s.centre[0], y - s.centre[1], heading_, right, up);
    return ImVec2(c.x + pxPerMetre * static_cast<float>(right), c.y - pxPerMetre * static_cast<float>(up));
  };
  for (const render::ZoneMarker& z : s.forbidden) {
    if (z.circle) {
      dl->AddCircleFilled(at(z.centre[0], z.centre[1]), pxPerMetre * static_cast<float>(z.radius),
                          colour(0.85f, 0.1f, 0.1f, 0.45f), 32);
      dl->AddCircle(at(z.centre[0], z.centre[1]), pxPerMetre * static_cast<float>(z.radius), colour(0.7f, 0.05f, 0.05f),
                    32, 2.0f * scale);
    } else {
      const ImVec2 q[4] = {at(z.min[0], z.min[1]), at(z.max[0], z.min[1]), at(z.max[0], z.max[1]),
                           at(z.min[0], z.max[1])};
      dl->AddConvexPolyFilled(q, 4, colour(0.85f, 0.1f, 0.1f, 0.45f));
      dl->AddPolyline(q, 4, colour(0.7f, 0.05f, 0.05f), ImDrawFlags_Closed, 2.0f);
    }
  }
  for (const render::TargetMarker& t : s.targets) {
    const double reach = 4.0 * span;  // a free band's half-width, past the map's edge
    const double hx = std::min(t.halfWidth[0], reach), hy = std::min(t.halfWidth[1], reach);
    const double x = t.halfWidth[0] < kFreeBand ? t.position[0] : s.centre[0];
    const double y = t.halfWidth[1] < kFreeBand ? t.position[1] : s.centre[1];
    const ImVec2 q[4] = {at(x - hx, y - hy), at(x + hx, y - hy), at(x + hx, y + hy), at(x - hx, y + hy)};
    dl->AddConvexPolyFilled(q, 4, t.inside ? colour(0.15f, 0.9f, 0.35f, 0.6f) : colour(0.1f, 0.65f, 0.25f, 0.4f));
    dl->AddPolyline(q, 4, colour(0.05f, 0.45f, 0.15f), ImDrawFlags_Closed, 2.0f);
  }
  for (std::size_t i = 1; i < s.examplePath.size(); i += 2)
    dl->AddLine(at(s.examplePath[i - 1][0], s.examplePath[i - 1][1]), at(s.examplePath[i][0], s.examplePath[i][1]),
                colour(0.25f, 0.8f, 1.0f), 1.5f);
  if (s.trace)
    for (std::size_t i = 1; i < s.trace->size(); ++i) {
      const render::TracePoint& a = s.trace->at(i - 1);
      const render::TracePoint& b = s.trace->at(i);
      const float alpha = static_cast<float>(s.trace->alphaForAge(s.time - b.time));
      dl->AddLine(at(a.x, a.y), at(b.x, b.y), colour(0.95f, 0.45f, 0.05f, alpha), 1.5f * scale);
    }
  if (proxyPath_)
    for (std::size_t i = 1; i < proxyPath_->size(); ++i) {
      const render::TracePoint& a = proxyPath_->at(i - 1);
      const render::TracePoint& b = proxyPath_->at(i);
      const float alpha = static_cast<float>(proxyPath_->alphaForAge(s.time - b.time));
      dl->AddLine(at(a.x, a.y), at(b.x, b.y), colour(0.2f, 0.4f, 1.0f, alpha), 1.5f * scale);
    }
  dl->AddCircleFilled(c, 4.0f * scale, colour(0.1f, 0.1f, 0.12f));  // the contact point: you are here
  // The scale bar: half the span, bottom left.
  const float bar = pxPerMetre * static_cast<float>(span / 2);
  const ImVec2 b0(o.x + 8 * scale, o.y + side - 10 * scale);
  dl->AddLine(b0, ImVec2(b0.x + bar, b0.y), colour(0.1f, 0.1f, 0.12f), 2.0f * scale);
  char label[32];
  const double half = span / 2;
  if (half < 0.01) std::snprintf(label, sizeof label, "%.1f mm", half * 1e3);
  else std::snprintf(label, sizeof label, "%.0f %s", half < 0.1 ? half * 1e3 : half * 1e2, half < 0.1 ? "mm" : "cm");
  dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(b0.x, b0.y - ImGui::GetFontSize() - 2 * scale),
              colour(0.1f, 0.1f, 0.12f), label);
  dl->PopClipRect();
  ImGui::TextDisabled("the floor, magnified");
  if (rects) rects->noteCurrentWindow("floor");
  ImGui::End();
}

}  // namespace hemiroll::game
