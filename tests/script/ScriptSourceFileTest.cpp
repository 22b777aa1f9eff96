// engine/script/ScriptSourceFile: reading a Lua data file as the stand-alone
// interpreter does.

#include "engine/script/ScriptSourceFile.h"

#include <sys/stat.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

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
    EXPECT_THAT(e.what(), ::testing::EndsWith(":1: not a regular file (a directory)"));
  }
}

// Refused before a byte is read: a FIFO would block the open for ever, and
// /dev/zero or a 3 GB sparse file would be read whole (issue 19).
TEST(ScriptSourceFile, FifosDevicesAndHugeFilesAreRefusedUnread) {
  test::TempDirectory dir;
  const std::string fifo = (dir.path() / "fifo.lua").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& path : {fifo, std::string("/dev/zero")}) {
    try {
      readScriptText(path, "bot file");
      FAIL() << path;
    } catch (const ScriptError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr(":1: not a regular file (a ")) << path;
    }
  }
  const std::string huge = (dir.path() / "huge.lua").string();
  std::filesystem::resize_file(dir.write("huge.lua", ""), std::uintmax_t{3} << 30);  // sparse: no disk used
  try {
    readScriptText(huge, "level file");
    FAIL();
  } catch (const ScriptError& e) {
    EXPECT_THAT(e.what(), ::testing::EndsWith("huge.lua:1: the level file is 3 GiB, more than the 4 MiB a level file may hold"));
  }
  // Under a smaller limit of the caller's, that limit is named.
  const std::string five = dir.write("five.lua", "return {}   ");
  try {
    readScriptText(five, "level file", 5, "memory limit");
    FAIL();
  } catch (const ScriptError& e) {
    EXPECT_THAT(e.what(), ::testing::EndsWith("five.lua:1: file is larger than the memory limit"));
  }
}

}  // namespace
}  // namespace hemiroll::script
