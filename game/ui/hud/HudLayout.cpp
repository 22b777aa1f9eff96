#include "game/ui/hud/HudLayout.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/render/Camera.h"

namespace hemiroll::game {

WindowRect hemisphereRect(const render::RenderScene& scene, float width, float height) {
  WindowRect r{"hemisphere", width / 2, height / 2, 0, 0};
  if (!(width > 0.0f) || !(height > 0.0f)) return r;
  const render::CameraView view = render::makeCameraView(scene.camera, scene.centre, scene.radius, width / height);
  // The ball's outline from points on it: 12 meridians x 7 parallels is
  // within 1 % of the true silhouette at these distances.
  float x0 = width, y0 = height, x1 = 0.0f, y1 = 0.0f;
  bool any = false;
  for (int i = 0; i < 12; ++i) {
    const double lon = 2.0 * std::numbers::pi * i / 12.0;
    for (int j = -3; j <= 3; ++j) {
      const double lat = std::numbers::pi / 2.0 * j / 3.0;
      const render::Vec3d p{scene.centre[0] + scene.radius * std::cos(lat) * std::cos(lon),
                            scene.centre[1] + scene.radius * std::cos(lat) * std::sin(lon),
                            scene.centre[2] + scene.radius * std::sin(lat)};
      const render::PixelPoint q = render::projectToPixel(view, p, static_cast<int>(width), static_cast<int>(height));
      if (!std::isfinite(q.x) || !std::isfinite(q.y)) continue;
      x0 = std::min(x0, static_cast<float>(q.x));
      x1 = std::max(x1, static_cast<float>(q.x));
      y0 = std::min(y0, static_cast<float>(q.y));
      y1 = std::max(y1, static_cast<float>(q.y));
      any = true;
    }
  }
  if (!any) return r;
  constexpr float kMargin = 4.0f;  // [px] the outline's antialiasing and the sampling's 1 %
  x0 = std::max(0.0f, x0 - kMargin);
  y0 = std::max(0.0f, y0 - kMargin);
  x1 = std::min(width, x1 + kMargin);
  y1 = std::min(height, y1 + kMargin);
  return WindowRect{"hemisphere", x0, y0, std::max(0.0f, x1 - x0), std::max(0.0f, y1 - y0)};
}

PanelPlace firstFreePlace(std::initializer_list<PanelPlace> places, float width, float height,
                          std::span<const WindowRect> taken, float displayWidth, float displayHeight, float margin) {
  for (const PanelPlace& p : places) {
    const WindowRect r{"panel", p.x, p.y, width, height};
    if (p.x < margin || p.y < margin || p.x + width > displayWidth - margin || p.y + height > displayHeight - margin)
      continue;
    bool free = true;
    for (const WindowRect& t : taken) free = free && !(t.width > 0 && t.height > 0 && r.overlaps(t));
    if (free) return p;
  }
  return places.size() ? *places.begin() : PanelPlace{};
}

}  // namespace hemiroll::game
