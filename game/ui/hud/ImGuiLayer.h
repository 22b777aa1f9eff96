#pragma once
// Dear ImGui (Debian's libimgui-dev 1.86) on the game's window: one context,
// the OpenGL 3 backend for drawing, and input fed from engine/platform's
// InputEvents rather than SDL's backend, because the window hands out
// InputEvents only (and tests inject the same events the player makes).
//
// ImGui 1.86 reads input as state per frame, so a press and a release that
// arrive in the same frame would never be seen as a click: a release is held
// back to the next frame when its press came in this one.

#include <memory>
#include <vector>

#include "engine/platform/InputEvent.h"

struct ImGuiStyle;  // imgui.h, which the window's library keeps private

namespace hemiroll::game {

// The font scale the interface was designed at (ImGui's 13 px font, 1.4x).
inline constexpr float kBaseFontScale = 1.4f;

// The interface's current scale (1 = as designed): the HUD multiplies its
// drawn sizes (dials, maps, plots) by it, so that they grow with the text.
// Inside an ImGui frame.
float uiScale();

class ImGuiLayer {
 public:
  // Needs a current GL 3.3 context. Throws std::runtime_error when the
  // backend cannot start.
  ImGuiLayer();
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // Returns true when ImGui takes the event (the pointer is over one of its
  // windows); the game then does not also use it.
  bool feed(const platform::InputEvent& event);
  // Starts a frame: window size [layout px], drawable size [GL px], step [s].
  void beginFrame(int width, int height, int drawableWidth, int drawableHeight, double dt);
  // Draws what the frame built into the bound framebuffer.
  void endFrame();
  bool wantsPointer() const;
  // Text and spacing at `scale` times the designed size (from the next
  // frame; clamped to [0.5, 4]).
  void setScale(double scale);
  double scale() const { return scale_; }

 private:
  bool pressedThisFrame_[3] = {false, false, false};
  bool releasePending_[3] = {false, false, false};
  double scale_ = 1.0;
  std::unique_ptr<ImGuiStyle> designed_;  // the style at scale 1, which setScale() multiplies
};

}  // namespace hemiroll::game
