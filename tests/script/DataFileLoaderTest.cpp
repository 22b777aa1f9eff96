// engine/script/DataFileLoader: the one path from a Lua data file to a
// definition. Its own rules (the field's line, Lua's line kept, the size
// limit, a chunk that returns no table) with a reader of its own, then the
// same through each of the four loaders that stand on it.

#include "engine/script/DataFileLoader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>

#include "engine/script/LevelLoader.h"
#include "engine/script/ProtocolLoader.h"
#include "engine/script/ScenarioLoader.h"
#include "engine/script/ScriptError.h"
#include "engine/script/SweepLoader.h"
#include "tests/support/ErrorMessage.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::script {
namespace {

using ::testing::StartsWith;

constexpr DataFileKind kTestKind{"test file", "test"};

const char* kNested = "return {\n  a = 1,\n  b = {\n    c = 2,\n  },\n}\n";

// What loading `source` as "f.lua" throws when `read` fails on its table.
std::string errorOf(std::string_view source, const std::function<void(const LuaTableReader&)>& read,
                    const SandboxLimits& limits = {}) {
  return test::messageOf<ScriptError>([&] {
    DataFileLoader(kTestKind, limits).loadSource(source, "f.lua", [&](const DataTable& data) {
      read(data.top);
      return 0;
    });
  });
}

TEST(DataFileLoader, HandsTheReturnedTableToTheReader) {
  const double c = DataFileLoader(kTestKind, {}).loadSource(kNested, "f.lua", [](const DataTable& data) {
    return *data.top.table("b")->number("c");
  });
  EXPECT_EQ(c, 2.0);
}

TEST(DataFileLoader, AFieldErrorGetsTheLineOfTheField) {
  EXPECT_EQ(errorOf(kNested, [](const LuaTableReader& top) { top.table("b")->fail("c", "too big"); }),
            "f.lua:4: b.c: too big");
  // Absent (or computed): the line of the nearest written parent.
  EXPECT_EQ(errorOf(kNested, [](const LuaTableReader& top) { top.table("b")->fail("x", "missing"); }),
            "f.lua:3: b.x: missing");
  // The table itself: the line of the returned constructor.
  EXPECT_EQ(errorOf(kNested, [](const LuaTableReader& top) { top.fail("", "empty"); }), "f.lua:1: empty");
  // A read that fails on its own (a wrong type) is a field error as well.
  EXPECT_EQ(errorOf(kNested, [](const LuaTableReader& top) { top.table("b")->string("c"); }),
            "f.lua:4: b.c: expected a string, got number");
}

TEST(DataFileLoader, AKeyThatIsNoNameGetsItsOwnLineToo) {
  // The field comes as a value: a space or ": " in a key does not confuse it.
  const char* source = "return {\n  a = 1,\n  b = {\n    ['c d: e'] = 2,\n  },\n}\n";
  EXPECT_EQ(errorOf(source, [](const LuaTableReader& top) { top.table("b")->fail("c d: e", "unknown"); }),
            "f.lua:4: b.c d: e: unknown");
}

TEST(DataFileLoader, AChunkThatFailsKeepsLuasFileAndLine) {
  const auto never = [](const LuaTableReader&) { FAIL() << "the reader must not run"; };
  EXPECT_EQ(errorOf("return {\n  a = 1,\n  b = nil + 1,\n}", never),
            "f.lua:3: attempt to perform arithmetic on a nil value");
  EXPECT_EQ(errorOf("\n\nerror('no')", never), "f.lua:3: no");
  EXPECT_EQ(errorOf("return {\n  a = ,\n}", never), "f.lua:2: unexpected symbol near ','");
}

TEST(DataFileLoader, AFailureWithoutAPlaceGetsTheReturnedTablesLine) {
  SandboxLimits small;
  small.memoryLimitBytes = std::size_t{1} << 20;
  EXPECT_EQ(errorOf("local s = string.rep('x', 1 << 22)\nreturn {\n}", [](const LuaTableReader&) {}, small),
            "f.lua:2: memory limit of 1 MiB exceeded");
  // Lines of other files (a module's) go behind the file being loaded.
  EXPECT_EQ(errorOf(kNested, [](const LuaTableReader&) { throw ScriptError("lib/vec.lua:4: bad"); }),
            "f.lua:1: lib/vec.lua:4: bad");
}

TEST(DataFileLoader, AChunkMustReturnATable) {
  EXPECT_EQ(errorOf("\nreturn 'x'", [](const LuaTableReader&) {}), "f.lua:2: the test must return a table, got string");
  EXPECT_EQ(errorOf("local a = 1", [](const LuaTableReader&) {}), "f.lua:1: the test must return a table, got nil");
}

TEST(DataFileLoader, ReadsFilesAsTheInterpreterDoes) {
  const test::TempDirectory dir;
  const std::string path = dir.write("f.lua", "\xEF\xBB\xBF#!/usr/bin/env lua\nreturn {\n  a = 'x',\n}\n");
  const std::string message = test::messageOf<ScriptError>([&] {
    DataFileLoader(kTestKind, {}).loadFile(path, [](const DataTable& data) { return *data.top.number("a"); });
  });
  EXPECT_EQ(message, path + ":3: a: expected a number, got string");
  EXPECT_EQ(test::messageOf<ScriptError>([&] { DataFileLoader(kTestKind, {}).readFile(dir.path() / "none.lua"); }),
            (dir.path() / "none.lua").string() + ":1: no such file");
}

// ---- The four kinds, each through its own loader.

struct Kind {
  const char* name;
  // Loads `source` as "k.lua", or the file at `path`, under `limits`.
  std::function<void(const std::string& source, const SandboxLimits& limits)> loadSource;
  std::function<void(const std::string& path, const SandboxLimits& limits)> loadFile;
  const char* badField;  // a source whose field on line 4 is wrong
  const char* expected;  // the message for it
};

// A level or protocol loader whose options are the defaults but `limits`.
template <class Loader, class Options>
Loader withLimits(const SandboxLimits& limits) {
  Options options;
  options.limits = limits;
  return Loader(options);
}

const Kind kKinds[] = {
    {"level",
     [](const std::string& s, const SandboxLimits& l) {
       withLimits<LevelLoader, LevelLoadOptions>(l).loadSource(s, "k.lua");
     },
     [](const std::string& p, const SandboxLimits& l) {
       withLimits<LevelLoader, LevelLoadOptions>(l).loadFile(p);
     },
     "return {\n  name = 'x',\n  force = {\n    kr = -5,\n  },\n}",
     "k.lua:4: force.kr: (stiffness) must be a finite, non-negative N/m"},
    {"protocol",
     [](const std::string& s, const SandboxLimits& l) {
       withLimits<ProtocolLoader, ProtocolLoadOptions>(l).loadSource(s, "k.lua", ".");
     },
     [](const std::string& p, const SandboxLimits& l) {
       withLimits<ProtocolLoader, ProtocolLoadOptions>(l).loadFile(p);
     },
     "return {\n  experiment = 'e',\n  blocks = {\n    { levle = 'x.lua' },\n  },\n}",
     "k.lua:4: blocks[1].levle: unknown key 'levle' (did you mean 'level'?)"},
    {"sweep",
     [](const std::string& s, const SandboxLimits& l) { SweepLoader(l).loadSource(s, "k.lua"); },
     [](const std::string& p, const SandboxLimits& l) { SweepLoader(l).loadFile(p); },
     "return {\n  axes = {\n    { param = 'k',\n      values = { 1, 2, 2 } },\n  },\n}",
     "k.lua:4: axes[1].values[3]: repeats an earlier value; each value once"},
    {"scenario",
     [](const std::string& s, const SandboxLimits& l) { ScenarioLoader(l).loadSource(s, "k.lua"); },
     [](const std::string& p, const SandboxLimits& l) { ScenarioLoader(l).loadFile(p); },
     "return {\n  drive = {\n    kind = 'rose',\n    r2 = -0.001,\n  },\n}",
     "k.lua:4: drive.r2: must be a non-negative length in metres"},
};

class DataFileKindTest : public ::testing::TestWithParam<Kind> {
 protected:
  std::string errorOfSource(const std::string& source, const SandboxLimits& limits = {}) const {
    return test::messageOf<ScriptError>([&] { GetParam().loadSource(source, limits); });
  }
  std::string errorOfFile(const std::string& path, const SandboxLimits& limits = {}) const {
    return test::messageOf<ScriptError>([&] { GetParam().loadFile(path, limits); });
  }
};

TEST_P(DataFileKindTest, AFieldErrorNamesTheLineOfTheField) {
  EXPECT_EQ(errorOfSource(GetParam().badField), GetParam().expected);
}

TEST_P(DataFileKindTest, AFileLargerThanTheMemoryLimitIsRefusedUnread) {
  const test::TempDirectory dir;
  SandboxLimits small;
  small.memoryLimitBytes = 1000;  // the text alone would not fit: refused before it runs
  const std::string path = dir.write("big.lua", "return {}\n--" + std::string(2000, 'x'));
  EXPECT_EQ(errorOfFile(path, small), path + ":1: file is larger than the memory limit");
}

TEST_P(DataFileKindTest, AChunkThatErrorsNamesFileAndLine) {
  EXPECT_EQ(errorOfSource("local t = {}\n\nreturn t.a.b"), "k.lua:3: attempt to index a nil value (field 'a')");
  const test::TempDirectory dir;
  const std::string path = dir.write("run.lua", "#!/usr/bin/env hemiroll\n\nerror('stop here')\n");
  EXPECT_EQ(errorOfFile(path), path + ":3: stop here");
}

TEST_P(DataFileKindTest, AChunkMustReturnATable) {
  EXPECT_THAT(errorOfSource("return 42"), StartsWith("k.lua:1: the "));
  EXPECT_THAT(errorOfSource("return 42"), ::testing::EndsWith(" must return a table, got number"));
}

INSTANTIATE_TEST_SUITE_P(Kinds, DataFileKindTest, ::testing::ValuesIn(kKinds),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace hemiroll::script
