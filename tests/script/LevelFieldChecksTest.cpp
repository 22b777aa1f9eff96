// engine/script/LevelFieldChecks: typed reads of level tables and the
// unknown-key check with its suggestion.

#include "engine/script/LevelFieldChecks.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <lua.hpp>

#include "engine/script/LuaSandbox.h"
#include "engine/script/ScriptError.h"
#include "tests/support/ErrorMessage.h"

namespace hemiroll::script {
namespace {

using ::testing::HasSubstr;

class LevelFieldChecks : public ::testing::Test {
 protected:
  // Runs `source` (which returns a table) and reads it as "t.lua", path "tab".
  LuaTableReader table(const std::string& source) {
    sandbox_.runChunk(source, "t.lua", 1);
    return LuaTableReader(sandbox_.state(), -1, "t.lua", "tab");
  }
  template <class F>
  std::string errorOf(F read) {
    return test::messageOf<ScriptError>(read);
  }
  LuaSandbox sandbox_;
};

TEST_F(LevelFieldChecks, UnknownKeysNameTheFirstAndSuggestTheNearest) {
  const LuaTableReader t = table("return { hold = 1, tol = 2, zzz = 3, tolerance = 4 }");
  EXPECT_EQ(errorOf([&] { rejectUnknownLevelKeys(t, {"hold", "tol"}); }),
            "t.lua: tab.tolerance: unknown key 'tolerance' (expected one of: hold, tol)");
  const LuaTableReader u = table("return { tl = 1 }");
  EXPECT_EQ(errorOf([&] { rejectUnknownLevelKeys(u, {"hold", "tol"}); }),
            "t.lua: tab.tl: unknown key 'tl' (did you mean 'tol'?)");
  const LuaTableReader v = table("return { 5 }");
  EXPECT_THAT(errorOf([&] { rejectUnknownLevelKeys(v, {"hold"}); }), HasSubstr("unexpected entry [1]"));
  EXPECT_EQ(errorOf([&] { rejectUnknownLevelKeys(table("return { hold = 1 }"), {"hold"}); }), "no error");
}

TEST_F(LevelFieldChecks, NearestNameNeedsEditDistanceTwoOrLess) {
  EXPECT_STREQ(nearestName("tragets", {"targets", "hold"}), "targets");
  EXPECT_STREQ(nearestName("hodl", {"targets", "hold"}), "hold");
  EXPECT_EQ(nearestName("zebra", {"targets", "hold"}), nullptr);
}

TEST_F(LevelFieldChecks, TypedReads) {
  const LuaTableReader t =
      table("return { yes = true, n = 3, half = 2.5, neg = -1, s = 'x', v2 = {1, 2}, v3 = {1, 2}, bad = {1, 'a'} }");
  EXPECT_EQ(readBool(t, "yes"), true);
  EXPECT_FALSE(readBool(t, "missing").has_value());
  EXPECT_THAT(errorOf([&] { readBool(t, "n"); }), HasSubstr("tab.n: expected true or false, got number"));
  EXPECT_EQ(readInteger(t, "n", 1, 5), 3);
  EXPECT_THAT(errorOf([&] { readInteger(t, "half", 1, 5); }), HasSubstr("expected a whole number from 1 to 5"));
  EXPECT_THAT(errorOf([&] { readInteger(t, "n", 4, 5); }), HasSubstr("expected a whole number from 4 to 5"));
  EXPECT_EQ(readPositive(t, "half", "m"), 2.5);
  EXPECT_THAT(errorOf([&] { readPositive(t, "neg", "m"); }), HasSubstr("must be a positive number (m)"));
  const auto v2 = readVector<2>(t, "v2", "{x, y}");
  ASSERT_TRUE(v2.has_value());
  EXPECT_EQ((*v2)[1], 2.0);
  EXPECT_THAT(errorOf([&] { readVector<3>(t, "v3", "{x, y, z}"); }), HasSubstr("tab.v3: expected {x, y, z} (2 entries given)"));
  EXPECT_THAT(errorOf([&] { readVector<2>(t, "bad", "{x, y}"); }), HasSubstr("tab.bad[2]: expected a number, got string"));
  EXPECT_THAT(errorOf([&] { readVector<2>(t, "s", "{x, y}"); }), HasSubstr("tab.s: expected {x, y}, got string"));
}

TEST_F(LevelFieldChecks, PositionKeysAreBracketed) {
  EXPECT_EQ(positionKey(12), "[12]");
  EXPECT_EQ(bracketed("table key"), "[table key]");
}

}  // namespace
}  // namespace hemiroll::script
