// game/ui/settings/KeyBindings: the play keys a player may change. No key does two
// things, no action is left without a key, Escape stays the way out.
#include "game/ui/settings/KeyBindings.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "engine/platform/KeyNames.h"

namespace hemiroll::game {
namespace {

std::int32_t code(const char* name) { return platform::keyFromName(name); }

void expectEveryActionItsOwnKey(const KeyBindings& keys) {
  std::set<std::int32_t> seen;
  for (int i = 0; i < kKeyActionCount; ++i) {
    const auto action = static_cast<KeyAction>(i);
    EXPECT_NE(keys.key(action), 0) << keyActionInfo(action).id;
    EXPECT_TRUE(seen.insert(keys.key(action)).second) << keyActionInfo(action).id << " shares its key";
    EXPECT_EQ(keys.actionOf(keys.key(action)), action);
  }
}

TEST(KeyBindingsTest, TheDefaultsAreTheOnesTheSettingsScreenNamed) {
  const KeyBindings keys;
  EXPECT_EQ(keys.keyName(KeyAction::TakeHold), "Space");
  EXPECT_EQ(keys.keyName(KeyAction::LetGo), "Backspace");
  EXPECT_EQ(keys.keyName(KeyAction::CycleCamera), "Tab");
  EXPECT_EQ(keys.keyName(KeyAction::OrbitLeft), "Left");
  EXPECT_EQ(keys.keyName(KeyAction::OrbitRight), "Right");
  EXPECT_EQ(keys.keyName(KeyAction::OrbitUp), "Up");
  EXPECT_EQ(keys.keyName(KeyAction::OrbitDown), "Down");
  EXPECT_EQ(keys.keyName(KeyAction::Hint), "H");
  expectEveryActionItsOwnKey(keys);
  EXPECT_FALSE(keys.actionOf(code("J")).has_value());
  EXPECT_FALSE(keys.actionOf(0).has_value());
}

TEST(KeyBindingsTest, AFreeKeyFreesTheOldOne) {
  KeyBindings keys;
  ASSERT_TRUE(keys.bind(KeyAction::TakeHold, code("J")));
  EXPECT_EQ(keys.actionOf(code("J")), KeyAction::TakeHold);
  EXPECT_FALSE(keys.actionOf(code("Space")).has_value());
  expectEveryActionItsOwnKey(keys);
}

TEST(KeyBindingsTest, AKeyAnotherActionHadIsSwapped) {
  KeyBindings keys;
  ASSERT_TRUE(keys.bind(KeyAction::TakeHold, code("Tab")));
  EXPECT_EQ(keys.keyName(KeyAction::TakeHold), "Tab");
  EXPECT_EQ(keys.keyName(KeyAction::CycleCamera), "Space");
  expectEveryActionItsOwnKey(keys);
  // Binding an action to its own key changes nothing.
  const KeyBindings before = keys;
  ASSERT_TRUE(keys.bind(KeyAction::TakeHold, code("Tab")));
  EXPECT_EQ(keys, before);
}

TEST(KeyBindingsTest, EscapeNoKeyAndNamelessKeysAreRefused) {
  KeyBindings keys;
  const KeyBindings before = keys;
  EXPECT_FALSE(keys.bind(KeyAction::TakeHold, code("Escape")));
  EXPECT_FALSE(keys.bind(KeyAction::LetGo, 0));
  // A scancode-keycode beyond SDL's table: no name, so it could not be saved.
  const std::int32_t nameless = (1 << 30) | 499;
  ASSERT_EQ(platform::keyName(nameless), "");
  EXPECT_FALSE(keys.bind(KeyAction::CycleCamera, nameless));
  EXPECT_EQ(keys, before);
}

TEST(KeyBindingsTest, EveryActionHasAnIdALabelAndAKnownDefault) {
  std::set<std::string> ids;
  for (int i = 0; i < kKeyActionCount; ++i) {
    const KeyActionInfo& info = keyActionInfo(static_cast<KeyAction>(i));
    EXPECT_TRUE(ids.insert(info.id).second) << info.id;
    EXPECT_NE(std::string(info.label), "");
    EXPECT_TRUE(KeyBindings::bindable(code(info.defaultKey))) << info.defaultKey;
  }
}

// A level's text names the player's key, not the default (issue 27: the
// hint moved to J, the text still said H).
TEST(KeyBindingsTest, TextsNameTheBoundKey) {
  KeyBindings keys;
  EXPECT_EQ(withKeyNames("Stuck? {key:hint} shows the autopilot's next move.", keys),
            "Stuck? H shows the autopilot's next move.");
  ASSERT_TRUE(keys.bind(KeyAction::Hint, code("J")));
  EXPECT_EQ(withKeyNames("Stuck? {key:hint} shows the autopilot's next move.", keys),
            "Stuck? J shows the autopilot's next move.");
  EXPECT_EQ(withKeyNames("{key:take_hold} then {key:let_go}", keys), "Space then Backspace");
  // Anything else in braces stays as written, an unclosed one too.
  EXPECT_EQ(withKeyNames("{key:fly} {x} {key:hint", keys), "{key:fly} {x} {key:hint");
  EXPECT_EQ(withKeyNames("", keys), "");
}

}  // namespace
}  // namespace hemiroll::game
