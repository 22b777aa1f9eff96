// engine/record/DurableFile: whole-file replacement that is all or nothing,
// and appends that land whole.

#include "engine/record/DurableFile.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "engine/record/RecordError.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::record {
namespace {

namespace fs = std::filesystem;

TEST(DurableFileTest, AtomicReplacementWritesTheWholeContent) {
  test::TempDirectory dir;
  const fs::path file = dir.path() / "map.svg";
  writeFileAtomically(file, "first");
  writeFileAtomically(file, "second");
  EXPECT_EQ(hemiroll::test::TempDirectory::read(file), "second");
  EXPECT_FALSE(fs::exists(dir.path() / "map.svg.tmp"));
}

TEST(DurableFileTest, AReplacementWhoseDirectorySyncIsDeferredIsAsWhole) {
  // Durable only with the folder's next sync (the sweep's first manifest),
  // but as visible and as whole at once.
  test::TempDirectory dir;
  const fs::path file = dir.path() / "sweep.json";
  writeFileAtomically(file, "first", DirectorySync::Deferred);
  writeFileAtomically(file, "second", DirectorySync::Deferred);
  EXPECT_EQ(hemiroll::test::TempDirectory::read(file), "second");
  EXPECT_FALSE(fs::exists(dir.path() / "sweep.json.tmp"));
}

TEST(DurableFileTest, AFailedReplacementLeavesNoTemporaryFile) {
  // A folder where the file should go: the rename fails, and the temporary
  // file went on lying beside it (issue 19: sweep map --out DIR left DIR.tmp).
  test::TempDirectory dir;
  const fs::path target = dir.path() / "out";
  fs::create_directories(target / "inside");
  EXPECT_THROW(writeFileAtomically(target, "content"), RecordError);
  EXPECT_FALSE(fs::exists(dir.path() / "out.tmp"));
  EXPECT_TRUE(fs::is_directory(target / "inside"));  // and the folder is untouched
}

TEST(DurableFileTest, AppendsLandWhole) {
  test::TempDirectory dir;
  const fs::path file = dir.path() / "results.csv";
  appendDurably(file, "a,b\n");
  appendDurably(file, "1,2\n");
  EXPECT_EQ(hemiroll::test::TempDirectory::read(file), "a,b\n1,2\n");
}

TEST(DurableFileTest, AFlushSkipsOnlyWhenNothingWasWrittenSinceTheLast) {
  // A flush after nothing new syncs nothing (DurableFile::flush); every write
  // after it must still reach the file at the next flush.
  test::TempDirectory dir;
  const fs::path file = dir.path() / "rows.csv";
  DurableFile out(file, "wb");
  ASSERT_TRUE(out.write("a\n") && out.flush());
  EXPECT_EQ(hemiroll::test::TempDirectory::read(file), "a\n");
  EXPECT_TRUE(out.flush());
  ASSERT_TRUE(out.write("b\n") && out.flush());
  EXPECT_EQ(hemiroll::test::TempDirectory::read(file), "a\nb\n");
  ASSERT_TRUE(out.writeAt(0, "A", 1) && out.flush());
  EXPECT_EQ(hemiroll::test::TempDirectory::read(file), "A\nb\n");
  EXPECT_TRUE(out.close());
}

TEST(DurableFileTest, AnAppendToAFileJustReplacedKeepsItsContent) {
  // The sweep's partial table: replaced atomically, then reopened for rows
  // without another sync of the folder (DurableFile::Entry::AlreadyCovered).
  test::TempDirectory dir;
  const fs::path file = dir.path() / "sweep.csv.partial";
  writeFileAtomically(file, "header\n");
  DurableFile out(file, "ab", DurableFile::Entry::AlreadyCovered);
  ASSERT_TRUE(out.write("row\n") && out.close());
  EXPECT_EQ(hemiroll::test::TempDirectory::read(file), "header\nrow\n");
}

}  // namespace
}  // namespace hemiroll::record
