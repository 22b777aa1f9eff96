#include "engine/files/CheckedFile.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "engine/files/FileReadError.h"
#include "tests/support/ErrorMessage.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::files {
namespace {

using ::testing::EndsWith;
using ::testing::HasSubstr;

constexpr FileKind kSmall{"small file", 16};

std::string errorOf(const std::filesystem::path& path, const FileKind& kind = kSmall) {
  return test::messageOf<FileReadError>([&] { readCheckedFile(path, kind); });
}

TEST(CheckedFile, ReadsARegularFileWhole) {
  const test::TempDirectory dir;
  const std::string path = dir.write("a.txt", std::string("line\n\0bytes", 11));
  EXPECT_EQ(readCheckedFile(path, kSmall), std::string("line\n\0bytes", 11));
  CheckedFile file(path, kSmall);
  EXPECT_EQ(file.size(), 11u);
  char buffer[4];
  EXPECT_EQ(file.read(buffer, sizeof buffer), 4u);
  EXPECT_EQ(file.readAll(), std::string("\n\0bytes", 7));  // the rest
}

// A FIFO would block an ordinary open until a writer came; the checked
// open does not wait, and refuses it by its type.
TEST(CheckedFile, RefusesAFifoWithoutBlocking) {
  const test::TempDirectory dir;
  const std::filesystem::path fifo = dir.path() / "pipe";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(errorOf(fifo), fifo.string() + ": not a regular file (a FIFO)");
}

TEST(CheckedFile, RefusesDevicesDirectoriesAndLinksToThem) {
  const test::TempDirectory dir;
  EXPECT_EQ(errorOf("/dev/zero"), "/dev/zero: not a regular file (a character device)");
  EXPECT_EQ(errorOf(dir.path()), dir.path().string() + ": not a regular file (a directory)");
  // A link is followed and what it leads to is checked.
  const std::filesystem::path link = dir.path() / "zero.json";
  std::filesystem::create_symlink("/dev/zero", link);
  EXPECT_EQ(errorOf(link), link.string() + ": not a regular file (a character device)");
}

// The size is checked before a byte is read: a 3 GB sparse file costs no
// time and no memory.
TEST(CheckedFile, RefusesAFileOverItsKindsCapUnread) {
  const test::TempDirectory dir;
  const std::string huge = dir.write("huge", "");
  std::filesystem::resize_file(huge, std::uintmax_t{3} << 30);
  EXPECT_EQ(errorOf(huge, kSidecar), huge + ": the trial sidecar is 3 GiB, more than the 1 MiB a trial sidecar may hold");
  const std::string seventeen = dir.write("seventeen", std::string(17, 'x'));
  EXPECT_THAT(errorOf(seventeen), EndsWith("is 17 bytes, more than the 16 bytes a small file may hold"));
  EXPECT_EQ(readCheckedFile(dir.write("sixteen", std::string(16, 'x')), kSmall).size(), 16u);
}

// A file that grows between the check and the read is cut at the cap, not
// read to its new end.
TEST(CheckedFile, StopsAFileThatGrowsPastTheCapWhileRead) {
  const test::TempDirectory dir;
  const std::string path = dir.write("growing", std::string(10, 'x'));
  CheckedFile file(path, kSmall);
  std::ofstream(path, std::ios::app) << std::string(100, 'y');
  EXPECT_THAT(test::messageOf<FileReadError>([&] { file.readAll(); }), HasSubstr("grew past the 16 bytes"));
}

TEST(CheckedFile, MissingFilesAreNamed) {
  const test::TempDirectory dir;
  EXPECT_EQ(errorOf(dir.path() / "none"), (dir.path() / "none").string() + ": no such file");
}

TEST(CheckedFile, TheNoThrowFormsSayTheSame) {
  const test::TempDirectory dir;
  const std::string path = dir.write("ok", "12345");
  const CheckedRead size = checkedSize(path.c_str(), kSmall);
  ASSERT_TRUE(size.ok);
  EXPECT_EQ(size.size, 5u);
  char buffer[5];
  const CheckedRead read = readCheckedInto(path.c_str(), kSmall, buffer, sizeof buffer);
  ASSERT_TRUE(read.ok);
  EXPECT_EQ(std::string(buffer, read.size), "12345");
  // A buffer too small for the file: the file changed since its size was taken.
  EXPECT_FALSE(readCheckedInto(path.c_str(), kSmall, buffer, 4).ok);
  const CheckedRead zero = checkedSize("/dev/zero", kSmall);
  EXPECT_FALSE(zero.ok);
  EXPECT_STREQ(zero.error, "/dev/zero: not a regular file (a character device)");
}

TEST(CheckedFile, SizesAreWrittenForPeople) {
  EXPECT_EQ(describeSize(1000), "1000 bytes");
  EXPECT_EQ(describeSize(4 * kMiB), "4 MiB");
  EXPECT_EQ(describeSize(3 * kGiB + kGiB / 2), "3.5 GiB");
}

}  // namespace
}  // namespace hemiroll::files
