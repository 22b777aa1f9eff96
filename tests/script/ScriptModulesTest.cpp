// engine/script/ScriptModules: require restricted to scripts/ (names
// validated, text only, cached, same sandbox) and the seeded hemiroll.random.

#include "engine/script/ScriptModules.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <lua.hpp>

#include "engine/script/LuaSandbox.h"
#include "engine/script/ScriptError.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::script {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

class ScriptModules : public ::testing::Test {
 protected:
  ScriptModules() {
    std::filesystem::create_directories(dir_.path() / "scripts" / "lib");
    dir_.write("scripts/lib/vec.lua", "local M = {}\nfunction M.add(a, b) return a + b end\nloads = (loads or 0) + 1\nreturn M");
    dir_.write("scripts/lib/broken.lua", "local M = {}\nerror('module failed')\nreturn M");
    dir_.write("scripts/lib/cycle_a.lua", "return require('lib.cycle_b')");
    dir_.write("scripts/lib/cycle_b.lua", "return require('lib.cycle_a')");
    dir_.write("scripts/lib/escape.lua", "return io or os or debug or package or load or 'sealed'");
    dir_.write("scripts/lib/nothing.lua", "local x = 1");
    dir_.write("scripts/lib/binary.lua", std::string("\x1bLua\x54\x00 fake bytecode", 21));
    dir_.write("secret.lua", "return 'outside scripts/'");
    installRequire(sandbox_, (dir_.path() / "scripts").string());
  }

  // Runs `source` and returns its one string or number result as text, or the error.
  std::string run(const std::string& source) {
    try {
      sandbox_.runChunk(source, "t.lua", 1);
    } catch (const ScriptError& e) {
      return std::string("error: ") + e.what();
    }
    std::string out = lua_tostring(sandbox_.state(), -1) ? lua_tostring(sandbox_.state(), -1) : "(not text)";
    lua_pop(sandbox_.state(), 1);
    return out;
  }

  test::TempDirectory dir_;
  LuaSandbox sandbox_;
};

TEST_F(ScriptModules, LoadsAModuleOnceAndCachesIt) {
  EXPECT_EQ(run("local a = require('lib.vec'); local b = require('lib.vec'); "
                "return tostring(a == b) .. ' ' .. a.add(2, 3) .. ' ' .. loads"),
            "true 5 1");
  EXPECT_EQ(run("return tostring(require('lib.nothing'))"), "true");  // nil result -> true
}

TEST_F(ScriptModules, RefusesEscapesAndBadNames) {
  for (const char* name : {"../secret", "lib/../../secret", "/etc/passwd", "lib..vec", ".lib", "lib.", "", "lib/vec",
                           "lib\\\\vec", "C:x"}) {
    const std::string result = run(std::string("return require('") + name + "')");
    EXPECT_THAT(result, StartsWith("error: t.lua:1: require(")) << name;
    EXPECT_THAT(result, HasSubstr("bad module name")) << name;
  }
  EXPECT_THAT(run("return require('lib.secret')"), HasSubstr("no module file"));
  EXPECT_THAT(run("return require({})"), HasSubstr("string expected, got table"));
}

TEST_F(ScriptModules, RefusesALinkOutOfTheScriptsFolder) {
  // A link inside scripts/ to a file outside it was followed, and the
  // file's text shown in the syntax error (it read /etc/shadow; issue 19).
  std::filesystem::create_symlink(dir_.path() / "secret.lua", dir_.path() / "scripts" / "lib" / "link.lua");
  const std::string result = run("return require('lib.link')");
  EXPECT_THAT(result, HasSubstr("leads outside the scripts folder"));
  EXPECT_THAT(result, Not(HasSubstr("outside scripts/'")));  // the secret's text is not shown
  // A link that stays inside is fine.
  std::filesystem::create_symlink(dir_.path() / "scripts" / "lib" / "vec.lua", dir_.path() / "scripts" / "lib" / "alias.lua");
  EXPECT_EQ(run("return require('lib.alias').add(1, 2)"), "3");
}

TEST_F(ScriptModules, RefusesBytecodeAndKeepsTheSandboxSealed) {
  EXPECT_THAT(run("return require('lib.binary')"), HasSubstr("precompiled (binary) Lua"));
  EXPECT_EQ(run("return require('lib.escape')"), "sealed");
}

TEST_F(ScriptModules, ModuleErrorsNameTheModuleFileAndLine) {
  const std::string result = run("return require('lib.broken')");
  EXPECT_THAT(result, HasSubstr("scripts/lib/broken.lua:2: module failed"));
  // A failed module is not cached as loaded: requiring it again fails the same way.
  EXPECT_THAT(run("return require('lib.broken')"), HasSubstr("broken.lua:2: module failed"));
}

TEST_F(ScriptModules, CircularRequireIsAnError) {
  EXPECT_THAT(run("return require('lib.cycle_a')"), HasSubstr("require('lib.cycle_a'): circular require"));
}

TEST(ScriptModulesPlain, WithoutInstallRequireThereIsNoRequire) {
  LuaSandbox sandbox;
  EXPECT_THROW(sandbox.runChunk("return require('lib.vec')", "t.lua", 1), ScriptError);
}

TEST(ScriptModulesPlain, ModuleNamesAreValidatedOutsideLuaToo) {
  std::string why;
  EXPECT_TRUE(validModuleName("bots.rose", why));
  EXPECT_EQ(why, "");
  EXPECT_FALSE(validModuleName("../x", why));
  EXPECT_NE(why, "");
  EXPECT_FALSE(validModuleName(std::string("a\0b", 3), why));
  EXPECT_EQ(defaultScriptsDir("levels/x.lua"), "levels/../scripts");
  EXPECT_EQ(defaultScriptsDir("x.lua"), "./../scripts");
}

// hemiroll.random: the same seed, the same sequence; ranges as documented.
std::vector<double> draws(std::uint64_t seed, const char* expression, int n) {
  LuaSandbox sandbox;
  installRandom(sandbox, seed);
  std::vector<double> out;
  const std::string source = std::string("local t = {} for i = 1, ") + std::to_string(n) + " do t[i] = " + expression +
                             " end return table.unpack(t)";
  sandbox.runChunk(source, "r.lua", n);
  for (int i = 1; i <= n; ++i) out.push_back(lua_tonumber(sandbox.state(), i));
  return out;
}

TEST(ScriptRandom, SameSeedSameSequenceOtherSeedOtherSequence) {
  EXPECT_EQ(draws(7, "hemiroll.random()", 50), draws(7, "hemiroll.random()", 50));
  EXPECT_NE(draws(7, "hemiroll.random()", 50), draws(8, "hemiroll.random()", 50));
}

TEST(ScriptRandom, RangesAreInclusiveIntegersAndHalfOpenFloats) {
  for (double x : draws(1, "hemiroll.random()", 200)) {
    EXPECT_GE(x, 0.0);
    EXPECT_LT(x, 1.0);
  }
  std::set<double> seen;
  for (double x : draws(2, "hemiroll.random(3, 5)", 200)) {
    EXPECT_EQ(x, std::floor(x));
    EXPECT_GE(x, 3.0);
    EXPECT_LE(x, 5.0);
    seen.insert(x);
  }
  EXPECT_EQ(seen.size(), 3u);  // 200 draws miss one of three values with probability ~3 (2/3)^200
  for (double x : draws(3, "hemiroll.random(4)", 100)) {
    EXPECT_GE(x, 1.0);
    EXPECT_LE(x, 4.0);
  }
}

TEST(ScriptRandom, BadArgumentsAndTheSeedAreReported) {
  LuaSandbox sandbox;
  installRandom(sandbox, 1234);
  EXPECT_THROW(sandbox.runChunk("return hemiroll.random(5, 1)", "r.lua", 1), ScriptError);
  EXPECT_THROW(sandbox.runChunk("return hemiroll.random(1.5)", "r.lua", 1), ScriptError);
  EXPECT_THROW(sandbox.runChunk("return hemiroll.random(1, 2, 3)", "r.lua", 1), ScriptError);
  sandbox.runChunk("return hemiroll.seed()", "r.lua", 1);
  EXPECT_EQ(lua_tointeger(sandbox.state(), -1), 1234);
  EXPECT_THROW(sandbox.runChunk("return math.random()", "r.lua", 1), ScriptError);  // still removed
}

}  // namespace
}  // namespace hemiroll::script
