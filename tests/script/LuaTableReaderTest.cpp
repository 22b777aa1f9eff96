// engine/script/LuaTableReader: typed reads with field paths in every message.

#include "engine/script/LuaTableReader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <lua.hpp>

#include "engine/script/LuaSandbox.h"
#include "engine/script/ScriptError.h"
#include "tests/support/ErrorMessage.h"

namespace hemiroll::script {
namespace {

using ::testing::HasSubstr;

// Runs `source` (which returns a table) and reads it as table "drive" of "f.lua".
class LuaTableReaderTest : public ::testing::Test {
 protected:
  LuaTableReader load(const std::string& source) {
    sandbox_.runChunk(source, "f.lua", 1);
    return LuaTableReader(sandbox_.state(), -1, "f.lua", "drive");
  }
  template <class Read>
  std::string errorOf(Read read) {
    return test::messageOf<ScriptError>(read);
  }
  LuaSandbox sandbox_;
};

TEST_F(LuaTableReaderTest, ReadsNumbersAndStrings) {
  const auto t = load("return {r1 = 0.015, k = 8, kind = 'rose'}");
  EXPECT_EQ(t.number("r1"), 0.015);
  EXPECT_EQ(t.number("k"), 8.0);
  EXPECT_EQ(t.number("absent"), std::nullopt);
  EXPECT_EQ(t.number("absent", 2.5), 2.5);
  EXPECT_EQ(t.string("kind"), "rose");
  EXPECT_EQ(t.fieldPath("r1"), "drive.r1");
}

TEST_F(LuaTableReaderTest, WrongTypesNameTheFieldPath) {
  const auto t = load("return {r1 = '0.015', kind = 3, sub = 1}");
  EXPECT_EQ(errorOf([&] { t.number("r1"); }), "f.lua: drive.r1: expected a number, got string");
  EXPECT_EQ(errorOf([&] { t.string("kind"); }), "f.lua: drive.kind: expected a string, got number");
  EXPECT_EQ(errorOf([&] { t.table("sub"); }), "f.lua: drive.sub: expected a table, got number");
}

TEST_F(LuaTableReaderTest, NonFiniteNumbersAreRefused) {
  const auto t = load("return {a = 1/0, b = -1/0, c = 0/0}");
  EXPECT_EQ(errorOf([&] { t.number("a"); }), "f.lua: drive.a: expected a finite number, got inf");
  EXPECT_EQ(errorOf([&] { t.number("b"); }), "f.lua: drive.b: expected a finite number, got -inf");
  EXPECT_EQ(errorOf([&] { t.number("c"); }), "f.lua: drive.c: expected a finite number, got nan");
}

TEST_F(LuaTableReaderTest, UnknownKeysAreListedSorted) {
  const auto t = load("return {kind = 'x', zeta = 1, alpha = 2, [1] = 3}");
  EXPECT_EQ(errorOf([&] { t.rejectUnknownKeys({"kind"}); }),
            "f.lua: drive: unknown fields 'alpha', 'zeta', [1] (expected one of: kind)");
  EXPECT_EQ(errorOf([&] { t.rejectUnknownKeys({"kind", "zeta", "alpha", "beta"}); }),
            "f.lua: drive: unknown field [1] (expected one of: kind, zeta, alpha, beta)");
}

TEST_F(LuaTableReaderTest, ReadsAreRawAndRunNoScriptCode) {
  const auto t = load(
      "return setmetatable({}, {__index = function() error('metamethod ran') end})");
  EXPECT_EQ(t.number("r1"), std::nullopt);
  EXPECT_EQ(t.typeOf("anything"), LUA_TNIL);
}

TEST_F(LuaTableReaderTest, NestedTablesExtendThePath) {
  const auto t = load("return {proxy = {1, 'two', 3}}");
  const auto proxy = t.table("proxy");
  ASSERT_TRUE(proxy.has_value());
  EXPECT_EQ(proxy->path(), "drive.proxy");
  EXPECT_EQ(proxy->numberAt(1), 1.0);
  EXPECT_EQ(proxy->entryCount(), 3);
  EXPECT_EQ(errorOf([&] { proxy->numberAt(2); }), "f.lua: drive.proxy[2]: expected a number, got string");
}

}  // namespace
}  // namespace hemiroll::script
