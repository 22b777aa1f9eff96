// Runs under Xvfb with Mesa's software GL (tests/platform/CMakeLists.txt).
#include "engine/platform/Window.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <vector>

#include "engine/platform/PlatformError.h"

namespace hemiroll::platform {
namespace {

TEST(WindowTest, OpensAGl33CoreContextAndSwaps) {
  auto window = Window::create({.title = "hemiroll WindowTest", .width = 320, .height = 200, .vsync = false});
  EXPECT_GE(epoxy_gl_version(), 33);
  GLint mask = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
  EXPECT_TRUE(mask & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_FALSE(window->glRenderer().empty());
  const PixelSize w = window->windowSize(), d = window->drawableSize();
  EXPECT_EQ(w.width, 320);
  EXPECT_EQ(w.height, 200);
  // High-DPI: the drawable is at least the window (equal on Xvfb, larger on Retina-like screens).
  EXPECT_GE(d.width, w.width);
  EXPECT_GE(d.height, w.height);
  glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  window->swap();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(WindowTest, PollEventsAppendsOnlyEventsTheEngineUses) {
  auto window = Window::create({.width = 64, .height = 64, .hidden = true});
  SDL_Event quit{};
  quit.type = SDL_QUIT;
  SDL_PushEvent(&quit);
  SDL_Event joystick{};
  joystick.type = SDL_JOYAXISMOTION;
  SDL_PushEvent(&joystick);
  std::vector<InputEvent> events;
  window->pollEvents(events);
  int quits = 0;
  for (const InputEvent& e : events) {
    EXPECT_NE(e.type, InputType::None);
    quits += e.type == InputType::Quit;
  }
  EXPECT_EQ(quits, 1);
}

TEST(WindowTest, BadSizeIsAClearError) {
  try {
    Window::create({.width = 0, .height = 10});
    FAIL() << "a zero-width window was created";
  } catch (const PlatformError& e) {
    EXPECT_NE(std::string(e.what()).find("0x10"), std::string::npos) << e.what();
  }
}

TEST(WindowTest, NoDisplayMessageSaysHowToRunHeadless) {
  const std::string m = noDisplayMessage("DISPLAY is not set");
  for (const char* needle : {"DISPLAY is not set", "hemiroll run", "hemiroll sim", "xvfb-run"})
    EXPECT_NE(m.find(needle), std::string::npos) << needle;
}

}  // namespace
}  // namespace hemiroll::platform
