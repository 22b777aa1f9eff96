// engine/script/ScriptSourceFile: reading a Lua data file as the stand-alone
// interpreter does, and giving a field's error the line it is written on.

#include "engine/script/ScriptSourceFile.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "engine/script/ScriptError.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::script {
namespace {

TEST(ScriptSourceFile, SkipsAByteOrderMarkAndBlanksAShebangKeepingLines) {
  test::TempDirectory dir;
  const std::string bom = dir.write("bom.lua", "\xEF\xBB\xBFreturn {}");
  EXPECT_EQ(readScriptText(bom, "level file"), "return {}");
  const std::string shebang = dir.write("sh.lua", "#!/usr/bin/lua\nreturn {}\n");
  EXPECT_EQ(readScriptText(shebang, "level file"), "\nreturn {}\n");
}

TEST(ScriptSourceFile, MissingOrNotAFileIsLineOne) {
  test::TempDirectory dir;
  try {
    readScriptText((dir.path() / "none.lua").string(), "protocol file");
    FAIL();
  } catch (const ScriptError& e) {
    EXPECT_THAT(e.what(), ::testing::EndsWith("none.lua:1: no such file"));
  }
  try {
    readScriptText(dir.path().string(), "protocol file");
    FAIL();
  } catch (const ScriptError& e) {
    EXPECT_THAT(e.what(), ::testing::EndsWith(":1: not a regular file"));
  }
}

TEST(ScriptSourceFile, AFieldsErrorGetsTheLineOfTheField) {
  const std::string source = "return {\n  a = 1,\n  b = {\n    c = 2,\n  },\n}\n";
  EXPECT_EQ(withSourceLine("f.lua: b.c: too big", "f.lua", source), "f.lua:4: b.c: too big");
  EXPECT_EQ(withSourceLine("f.lua: b.x: missing", "f.lua", source), "f.lua:3: b.x: missing");  // absent: its parent
  EXPECT_EQ(withSourceLine("f.lua:9: syntax", "f.lua", source), "f.lua:9: syntax");         // has its line already
  EXPECT_EQ(withSourceLine("out of memory", "f.lua", source), "f.lua:1: out of memory");
}

}  // namespace
}  // namespace hemiroll::script
