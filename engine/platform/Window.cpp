#include "engine/platform/Window.h"

#include <epoxy/gl.h>

#include <cstdlib>

#include "engine/platform/InputTranslator.h"
#include "engine/platform/PlatformError.h"

namespace hemiroll::platform {

namespace {

bool haveDisplayVariable() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 && *x11) || (wayland && *wayland);
}

void initVideo() {
  if (SDL_WasInit(SDL_INIT_VIDEO)) return;
  // Without a display variable SDL would try every driver and fail with a
  // driver-specific error; say what to do instead. SDL_VIDEODRIVER set by the
  // user (e.g. "offscreen") is respected.
  const char* driver = std::getenv("SDL_VIDEODRIVER");
  if (!haveDisplayVariable() && !(driver && *driver)) throw PlatformError(noDisplayMessage("DISPLAY is not set"));
  if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) throw PlatformError(noDisplayMessage(SDL_GetError()));
}

}  // namespace

std::string noDisplayMessage(const std::string& sdlError) {
  return "no display to open a window on (" + sdlError +
         "). hemiroll's window needs a desktop session. Headless, use `hemiroll run LEVEL --bot BOT` "
         "(a level played by a bot) or `hemiroll sim SCENARIO` (physics only); or run under a virtual "
         "display: `xvfb-run -a hemiroll ...`.";
}

std::unique_ptr<Window> Window::create(const WindowDef& def) {
  if (def.width <= 0 || def.height <= 0)
    throw PlatformError("window size " + std::to_string(def.width) + "x" + std::to_string(def.height) +
                        " must be positive");
  initVideo();
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);

  Uint32 flags = SDL_WINDOW_OPENGL;
  if (def.resizable) flags |= SDL_WINDOW_RESIZABLE;
  if (def.highDpi) flags |= SDL_WINDOW_ALLOW_HIGHDPI;
  flags |= def.hidden ? SDL_WINDOW_HIDDEN : SDL_WINDOW_SHOWN;
  SDL_Window* window = SDL_CreateWindow(def.title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                        def.width, def.height, flags);
  if (!window) throw PlatformError(std::string("cannot open a window: ") + SDL_GetError());
  SDL_GLContext context = SDL_GL_CreateContext(window);
  if (!context) {
    const std::string error = SDL_GetError();
    SDL_DestroyWindow(window);
    throw PlatformError("cannot create an OpenGL 3.3 core context (" + error +
                        "); with Mesa's software renderer set LIBGL_ALWAYS_SOFTWARE=1");
  }
  if (epoxy_gl_version() < 33) {
    SDL_GL_DeleteContext(context);
    SDL_DestroyWindow(window);
    throw PlatformError("the OpenGL context is older than 3.3");
  }
  std::unique_ptr<Window> created(new Window(window, context, false));
  created->setVsync(def.vsync);
  return created;
}

Window::Window(SDL_Window* window, SDL_GLContext context, bool vsync)
    : window_(window), context_(context), vsync_(vsync) {}

// Adaptive vsync (-1) first, then plain vsync; a driver without either
// still renders, just unpaced.
void Window::setVsync(bool on) {
  if (on) {
    vsync_ = SDL_GL_SetSwapInterval(-1) == 0 || SDL_GL_SetSwapInterval(1) == 0;
  } else {
    SDL_GL_SetSwapInterval(0);
    vsync_ = false;
  }
}

Window::~Window() {
  SDL_GL_DeleteContext(context_);
  SDL_DestroyWindow(window_);
}

PixelSize Window::windowSize() const {
  PixelSize s;
  SDL_GetWindowSize(window_, &s.width, &s.height);
  return s;
}

PixelSize Window::drawableSize() const {
  PixelSize s;
  SDL_GL_GetDrawableSize(window_, &s.width, &s.height);
  return s;
}

std::string Window::glRenderer() const {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return name ? name : "unknown";
}

void Window::pollEvents(std::vector<InputEvent>& out) {
  SDL_Event event;
  while (SDL_PollEvent(&event)) {
    const InputEvent translated = translateEvent(event);
    if (translated.type != InputType::None) out.push_back(translated);
  }
}

bool Window::capturePointer(bool captured) {
  return SDL_SetRelativeMouseMode(captured ? SDL_TRUE : SDL_FALSE) == 0;
}

void Window::swap() { SDL_GL_SwapWindow(window_); }

void Window::makeCurrent() { SDL_GL_MakeCurrent(window_, context_); }

}  // namespace hemiroll::platform
