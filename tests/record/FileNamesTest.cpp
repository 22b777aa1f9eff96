// engine/record/FileNames and ContentHash: the names and hashes that files
// carry, checked against the rules written out by hand.

#include "engine/record/FileNames.h"

#include <gtest/gtest.h>

#include "engine/record/ContentHash.h"

namespace hemiroll::record {
namespace {

TEST(FileNamesTest, SafeFileNamesCannotLeaveTheirFolder) {
  EXPECT_TRUE(isSafeFileName("trial-001_a.b"));
  for (const char* bad : {"", ".", "..", "a/b", "../x", "a b", "a\\b", "\xc3\xa9"})
    EXPECT_FALSE(isSafeFileName(bad)) << bad;
}

TEST(FileNamesTest, StemsKeepLettersDigitsAndWhatIsAsked) {
  EXPECT_EQ(fileStemOf("Stop on target!", "", "_"), "Stop_on_target_");
  EXPECT_EQ(fileStemOf("my-bot_2.lua", "-_", "trial"), "my-bot_2_lua");
  EXPECT_EQ(fileStemOf("", "-_", "trial"), "trial");
  // Bytes of a UTF-8 letter are not ASCII letters: one '_' each.
  EXPECT_EQ(fileStemOf("\xc3\xa9t\xc3\xa9", "", "_"), "__t__");
}

TEST(FileNamesTest, ContentHashIsFnv1aOfTheBytes) {
  // FNV-1a 64 of "" is its offset basis; of "a" the published test vector.
  EXPECT_EQ(contentHash(""), "fnv1a-cbf29ce484222325");
  EXPECT_EQ(contentHash("a"), "fnv1a-af63dc4c8601ec8c");
  EXPECT_EQ(fileContentHash("/no/such/file/anywhere"), "");
}

}  // namespace
}  // namespace hemiroll::record
