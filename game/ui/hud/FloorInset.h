#pragma once
// The floor round the contact point, magnified, in a corner of the screen:
// the targets, the forbidden zones, the contact trace and a level's example
// path as a map seen from above, turned like the camera (up is away from the
// camera, right is the mouse's right) with a scale bar. Millimetre targets
// and pits lie under the hemisphere in every camera; here they are never
// hidden, by the hemisphere or by the HUD.
//
// The scale is chosen from a few round spans (5 mm to 20 cm across half the
// map) with hysteresis, so that it does not breathe as the contact moves.

#include <array>

#include "engine/render/ContactTrace.h"
#include "engine/render/RenderScene.h"
#include "game/ui/hud/WindowRects.h"

namespace hemiroll::game {

class FloorInset {
 public:
  static constexpr std::array<double, 7> kSpans = {0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5};  // [m], half the map

  // Once per frame, from the scene the frame draws (its contact point is
  // under the sphere centre) and the camera's screen-right heading [rad].
  void update(const render::RenderScene& scene, double screenRightHeading);
  double span() const { return kSpans[spanIndex_]; }
  // A second path drawn over the contact's (a replay's proxy: where the hand
  // went), in blue; null = none. Must outlive the next draw().
  void setProxyPath(const render::ContactTrace* path) { proxyPath_ = path; }
  void draw(WindowRects* rects = nullptr) const;  // inside an ImGui frame

 private:
  const render::RenderScene* scene_ = nullptr;
  const render::ContactTrace* proxyPath_ = nullptr;
  double heading_ = 0.0;
  std::size_t spanIndex_ = 0;
  bool fitted_ = false;  // the first update fits the span from the smallest
};

// The span index for a target `needed` metres from the contact point:
// grown at once when it would fall off the map, shrunk only once it fits well
// inside the next smaller span (under 80 %: no flicker at a boundary).
std::size_t insetSpanIndex(std::size_t current, double needed);

}  // namespace hemiroll::game
