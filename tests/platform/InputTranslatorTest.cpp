#include "engine/platform/InputTranslator.h"

#include <gtest/gtest.h>

namespace hemiroll::platform {
namespace {

// Synthetic SDL events: the translator needs no window or video subsystem.
SDL_Event keyEvent(Uint32 type, SDL_Keycode sym, Uint8 repeat = 0) {
  SDL_Event e{};
  e.type = type;
  e.key.keysym.sym = sym;
  e.key.repeat = repeat;
  e.common.timestamp = 1500;
  return e;
}

TEST(InputTranslatorTest, KeysKnownAndOther) {
  InputEvent e = translateEvent(keyEvent(SDL_KEYDOWN, SDLK_ESCAPE));
  EXPECT_EQ(e.type, InputType::KeyDown);
  EXPECT_EQ(e.key, Key::Escape);
  EXPECT_DOUBLE_EQ(e.timestamp, 1.5);
  e = translateEvent(keyEvent(SDL_KEYUP, SDLK_KP_ENTER, 1));
  EXPECT_EQ(e.type, InputType::KeyUp);
  EXPECT_EQ(e.key, Key::Enter);
  EXPECT_TRUE(e.repeat);
  e = translateEvent(keyEvent(SDL_KEYDOWN, SDLK_q));
  EXPECT_EQ(e.key, Key::Other);
  EXPECT_EQ(e.code, SDLK_q);
}

TEST(InputTranslatorTest, PointerMotionAndButtonsInWindowPixels) {
  SDL_Event m{};
  m.type = SDL_MOUSEMOTION;
  m.motion.x = 321;
  m.motion.y = 45;
  m.motion.xrel = -3;
  m.motion.yrel = 12;
  InputEvent e = translateEvent(m);
  EXPECT_EQ(e.type, InputType::PointerMove);
  EXPECT_EQ(e.x, 321.0);
  EXPECT_EQ(e.y, 45.0);
  EXPECT_EQ(e.dx, -3.0);  // the motion: what steers the proxy
  EXPECT_EQ(e.dy, 12.0);

  SDL_Event b{};
  b.type = SDL_MOUSEBUTTONDOWN;
  b.button.button = SDL_BUTTON_RIGHT;
  b.button.x = 7;
  b.button.y = 9;
  e = translateEvent(b);
  EXPECT_EQ(e.type, InputType::ButtonDown);
  EXPECT_EQ(e.button, PointerButton::Right);
  EXPECT_EQ(e.x, 7.0);
}

TEST(InputTranslatorTest, WheelIsAwayPositiveEvenOnFlippedDevices) {
  SDL_Event w{};
  w.type = SDL_MOUSEWHEEL;
  w.wheel.y = 2;
  w.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
  EXPECT_EQ(translateEvent(w).wheel, 2.0);
  w.wheel.direction = SDL_MOUSEWHEEL_FLIPPED;
  EXPECT_EQ(translateEvent(w).wheel, -2.0);
}

TEST(InputTranslatorTest, WindowEventsQuitAndUnknown) {
  SDL_Event r{};
  r.type = SDL_WINDOWEVENT;
  r.window.event = SDL_WINDOWEVENT_SIZE_CHANGED;
  r.window.data1 = 800;
  r.window.data2 = 600;
  InputEvent e = translateEvent(r);
  EXPECT_EQ(e.type, InputType::Resized);
  EXPECT_EQ(e.x, 800.0);
  EXPECT_EQ(e.y, 600.0);
  r.window.event = SDL_WINDOWEVENT_FOCUS_LOST;
  EXPECT_EQ(translateEvent(r).type, InputType::FocusLost);
  r.window.event = SDL_WINDOWEVENT_MOVED;
  EXPECT_EQ(translateEvent(r).type, InputType::None);

  SDL_Event q{};
  q.type = SDL_QUIT;
  EXPECT_EQ(translateEvent(q).type, InputType::Quit);
  SDL_Event j{};
  j.type = SDL_JOYAXISMOTION;
  EXPECT_EQ(translateEvent(j).type, InputType::None);
}

}  // namespace
}  // namespace hemiroll::platform
