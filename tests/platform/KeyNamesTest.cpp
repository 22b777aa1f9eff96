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

}  // namespace
}  // namespace hemiroll::platform
