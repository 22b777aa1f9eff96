// engine/script/ScriptSourceFile: reading a Lua data file as the stand-alone
// interpreter does.

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

}  // namespace
}  // namespace hemiroll::script
