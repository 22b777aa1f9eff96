#pragma once
// Where the HUD's windows were drawn in the last frame, by name, so that a
// test can check a layout (nothing off screen, nothing on top of another)
// at any window size. Fixed room: noting a rect allocates nothing.

#include <array>
#include <cstddef>
#include <span>

namespace hemiroll::game {

struct WindowRect {
  const char* name = "";
  float x = 0, y = 0, width = 0, height = 0;  // [px], from the top left
  bool overlaps(const WindowRect& o) const {
    return x < o.x + o.width && o.x < x + width && y < o.y + o.height && o.y < y + height;
  }
  bool within(float displayWidth, float displayHeight) const {
    return x >= 0 && y >= 0 && x + width <= displayWidth && y + height <= displayHeight;
  }
};

class WindowRects {
 public:
  void clear() { count_ = 0; }
  // The current ImGui window's rect (call between Begin and End).
  void noteCurrentWindow(const char* name);
  std::span<const WindowRect> rects() const { return {rects_.data(), count_}; }

 private:
  std::array<WindowRect, 8> rects_{};
  std::size_t count_ = 0;
};

}  // namespace hemiroll::game
