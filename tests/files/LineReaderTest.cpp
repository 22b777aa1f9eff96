#include "engine/files/LineReader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "engine/files/FileReadError.h"
#include "tests/support/ErrorMessage.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::files {
namespace {

constexpr FileKind kTable{"table", 64 * kGiB};

std::vector<std::string> linesOf(const std::string& path, std::size_t maxLine, std::vector<bool>* complete = nullptr) {
  CheckedFile file(path, kTable);
  LineReader reader(file, maxLine);
  std::vector<std::string> out;
  std::string_view line;
  bool whole = false;
  while (reader.next(line, whole)) {
    out.emplace_back(line);
    if (complete) complete->push_back(whole);
    EXPECT_EQ(reader.lineNumber(), out.size());
  }
  return out;
}

TEST(LineReader, SplitsLinesAndSaysWhichOneWasCut) {
  const test::TempDirectory dir;
  std::vector<bool> complete;
  EXPECT_EQ(linesOf(dir.write("a", "one\r\ntwo\n\nlast"), 16, &complete),
            (std::vector<std::string>{"one", "two", "", "last"}));
  EXPECT_EQ(complete, (std::vector<bool>{true, true, true, false}));
  EXPECT_TRUE(linesOf(dir.write("empty", ""), 16).empty());
}

// Lines cross the reader's buffer (64 KiB) many times over: the text comes
// back whole and in order.
TEST(LineReader, LinesAcrossBufferBoundariesComeBackWhole) {
  const test::TempDirectory dir;
  std::string text;
  std::vector<std::string> expected;
  for (int i = 0; i < 20000; ++i) {
    expected.push_back(std::string(static_cast<std::size_t>(i % 97), static_cast<char>('a' + i % 26)) + std::to_string(i));
    text += expected.back() + "\n";
  }
  EXPECT_EQ(linesOf(dir.write("many", text), 200), expected);
}

// A file of zeros with no line end (a 3 GB sparse file, /dev/zero's like) is
// refused at the cap of one line, not read to its end.
TEST(LineReader, AnOverlongLineIsRefusedAtTheCap) {
  const test::TempDirectory dir;
  const std::string sparse = dir.write("sparse", "header\n");
  std::filesystem::resize_file(sparse, std::uintmax_t{3} << 30);
  CheckedFile file(sparse, kTable);
  LineReader reader(file, 1024);
  std::string_view line;
  ASSERT_TRUE(reader.next(line));
  EXPECT_EQ(line, "header");
  EXPECT_EQ(test::messageOf<FileReadError>([&] { reader.next(line); }),
            sparse + ": line 2: longer than the 1 KiB a line of a table may be");
  // Exactly at the cap is fine, one byte more is not.
  EXPECT_EQ(linesOf(dir.write("at", std::string(8, 'x') + "\n"), 8).size(), 1u);
  EXPECT_THAT(test::messageOf<FileReadError>([&] { linesOf(dir.write("over", std::string(9, 'x') + "\n"), 8); }),
              ::testing::HasSubstr("line 1: longer than the 8 bytes"));
  EXPECT_THAT(test::messageOf<FileReadError>([&] { linesOf(dir.write("cut", std::string(9, 'x')), 8); }),
              ::testing::HasSubstr("line 1: longer than the 8 bytes"));
}

}  // namespace
}  // namespace hemiroll::files
