#include "engine/platform/KeyNames.h"

#include <SDL.h>
#include <gtest/gtest.h>

namespace hemiroll::platform {
namespace {

// Without SDL_Init, as the settings file is read before the window opens.
TEST(KeyNamesTest, NamesOfTheDefaultBindingsAndBack) {
  EXPECT_EQ(keyName(SDLK_SPACE), "Space");
  EXPECT_EQ(keyName(SDLK_TAB), "Tab");
  EXPECT_EQ(keyName(SDLK_LEFT), "Left");
  EXPECT_EQ(keyName(SDLK_h), "H");
  for (SDL_Keycode code : {SDLK_SPACE, SDLK_TAB, SDLK_LEFT, SDLK_RIGHT, SDLK_UP, SDLK_DOWN, SDLK_h, SDLK_1, SDLK_F5,
                           SDLK_KP_5, SDLK_LSHIFT, SDLK_ESCAPE})
    EXPECT_EQ(keyFromName(keyName(code)), code) << keyName(code);
}

TEST(KeyNamesTest, LettersInEitherCaseAndUnknownNames) {
  EXPECT_EQ(keyFromName("h"), SDLK_h);
  EXPECT_EQ(keyFromName("H"), SDLK_h);
  EXPECT_EQ(keyFromName(""), 0);
  EXPECT_EQ(keyFromName("NoSuchKey"), 0);
  EXPECT_EQ(keyName(0), "");
}

// Synthetic key presses are made as the window makes real ones.
TEST(KeyNamesTest, KeyDownEventsAsTheWindowGivesThem) {
  InputEvent e = keyDownEvent("Return");
  EXPECT_EQ(e.type, InputType::KeyDown);
  EXPECT_EQ(e.key, Key::Enter);
  EXPECT_EQ(e.code, SDLK_RETURN);
  EXPECT_FALSE(e.repeat);
  e = keyDownEvent("Q");
  EXPECT_EQ(e.key, Key::Other);
  EXPECT_EQ(e.code, SDLK_q);
  EXPECT_EQ(keyDownEvent("Escape").key, Key::Escape);
}

}  // namespace
}  // namespace hemiroll::platform
