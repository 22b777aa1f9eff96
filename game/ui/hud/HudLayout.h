#pragma once
// Where the HUD's panels may go (issue 27: with four components out the
// top-left panel grew over the hemisphere at 1280x720). The camera always
// looks at the hemisphere, so it stands about the window's middle; its rect
// on screen is what every panel keeps clear of, and a panel that cannot
// keep its first place takes the next free one.

#include <initializer_list>
#include <span>

#include "engine/render/RenderScene.h"
#include "game/ui/hud/WindowRects.h"

namespace hemiroll::game {

// The hemisphere's bounding sphere projected into a width x height window
// [window px] (the whole ball: any tilt stays inside), with a small margin.
WindowRect hemisphereRect(const render::RenderScene& scene, float width, float height);

struct PanelPlace {
  float x = 0, y = 0;  // top left [px]
};

// The first of `places` where a `width` x `height` panel lies inside the
// display (with `margin`) and overlaps none of `taken`; the first place
// when none does (the layout tests then fail, naming it).
PanelPlace firstFreePlace(std::initializer_list<PanelPlace> places, float width, float height,
                          std::span<const WindowRect> taken, float displayWidth, float displayHeight,
                          float margin = 10.0f);

}  // namespace hemiroll::game
