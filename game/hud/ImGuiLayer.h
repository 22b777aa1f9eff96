#pragma once
// Dear ImGui (Debian's libimgui-dev 1.86) on the game's window: one context,
// the OpenGL 3 backend for drawing, and input fed from engine/platform's
// InputEvents rather than SDL's backend, because the window hands out
// InputEvents only (and tests inject the same events the player makes).
//
// ImGui 1.86 reads input as state per frame, so a press and a release that
// arrive in the same frame would never be seen as a click: a release is held
// back to the next frame when its press came in this one.

#include <vector>

#include "engine/platform/InputEvent.h"

namespace hemiroll::game {

class ImGuiLayer {
 public:
  // Needs a current GL 3.3 context. Throws std::runtime_error when the
  // backend cannot start.
  explicit ImGuiLayer(double fontScale = 1.4);
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

 private:
  bool pressedThisFrame_[3] = {false, false, false};
  bool releasePending_[3] = {false, false, false};
};

}  // namespace hemiroll::game
