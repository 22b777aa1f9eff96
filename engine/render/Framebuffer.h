#pragma once
// An offscreen render target: colour (RGBA8) and depth (24 bit)
// renderbuffers in a framebuffer object. Screenshots, tests and benchmarks
// draw here, so the result does not depend on a visible window (a hidden or
// covered window's own buffer is undefined under GL's pixel ownership rule).
// Needs a current GL context; move-only.

#include "engine/render/Image.h"

namespace hemiroll::render {

class Framebuffer {
 public:
  // Throws RenderError for a non-positive size or an incomplete framebuffer.
  Framebuffer(int width, int height);
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  void bind() const;           // draw here (and set the viewport)
  static void bindDefault();   // back to the window
  Image read() const;          // waits for the GPU; rows top-down
  // The window's back buffer (before the swap shows it), rows top-down.
  static Image readBackBuffer(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void release();
  int width_, height_;
  unsigned fbo_ = 0, color_ = 0, depth_ = 0;
};

}  // namespace hemiroll::render
