#include "tests/render/support/GlTestContext.h"

#include <gtest/gtest.h>

#include <memory>

#include "engine/platform/PlatformError.h"
#include "engine/platform/Window.h"

namespace hemiroll::test {

void useGlContext() {
  static std::unique_ptr<platform::Window> window;
  if (window) {
    window->makeCurrent();  // a test may have opened and closed a window of its own
    return;
  }
  try {
    window = platform::Window::create({.title = "hemiroll render tests", .width = 64, .height = 64,
                                       .vsync = false, .hidden = true});
  } catch (const platform::PlatformError& e) {
    FAIL() << e.what();
  }
}

}  // namespace hemiroll::test
