#pragma once
// The game's window: SDL2 + an OpenGL 3.3 core context (functions through
// libepoxy). Resizable, vsync on by default, high-DPI aware: the drawable
// size (GL pixels) may be larger than the window size (layout pixels), and
// the renderer must use the drawable size for its viewport.
//
// Offscreen use (screenshots, tests, benchmarks): `hidden = true` opens the
// same context behind a window that is never shown; draw into an
// engine/render Framebuffer, not into the window.
//
// No display: create() throws one PlatformError that says how to run
// headless (`hemiroll run`, `hemiroll sim`) or under a virtual display
// (`xvfb-run -a`). Never a crash.

#include <SDL.h>

#include <memory>
#include <string>
#include <vector>

#include "engine/platform/InputEvent.h"

namespace hemiroll::platform {

struct WindowDef {
  std::string title = "hemiroll";
  int width = 1280, height = 720;  // window size [layout px]
  bool resizable = true;
  bool vsync = true;               // off for benchmarks (frames as fast as they come)
  bool hidden = false;             // offscreen: a context without a visible window
  bool highDpi = true;             // ask for a full-resolution drawable on high-DPI screens
};

struct PixelSize {
  int width = 0, height = 0;
};

class Window {
 public:
  // Initialises SDL's video subsystem (once per process), opens the window
  // and makes its GL 3.3 core context current. Throws PlatformError.
  static std::unique_ptr<Window> create(const WindowDef& def = {});
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  PixelSize windowSize() const;    // layout pixels (pointer coordinates)
  PixelSize drawableSize() const;  // GL pixels (the viewport)
  // Whether the driver paces swaps to the display (it may refuse).
  bool vsync() const { return vsync_; }
  // Adaptive vsync first, then plain; off when `on` is false. The window's
  // context must be current on this thread.
  void setVsync(bool on);
  // The GL renderer's name ("llvmpipe (LLVM 15.0.6, 256 bits)"), for logs.
  std::string glRenderer() const;

  // Appends this frame's input (SDL's queue drained) to `out`; events the
  // engine does not use are left out. Reuse `out` across frames: no
  // allocation once its capacity suffices.
  void pollEvents(std::vector<InputEvent>& out);
  void swap();
  // Captured: the system cursor is hidden and the pointer reports motion
  // without end (no window edge), as the play screen steers by motion; the
  // game draws the proxy instead. False when the platform cannot (motion
  // then still arrives, bounded by the window).
  bool capturePointer(bool captured);
  // Makes this window's context current again (after another window's
  // context was used or destroyed on this thread).
  void makeCurrent();

 private:
  Window(SDL_Window* window, SDL_GLContext context, bool vsync);
  SDL_Window* window_;
  SDL_GLContext context_;
  bool vsync_;
};

// The message create() gives when there is no display; public for tests.
std::string noDisplayMessage(const std::string& sdlError);

}  // namespace hemiroll::platform
