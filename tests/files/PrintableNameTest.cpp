#include "engine/files/PrintableName.h"

#include <gtest/gtest.h>

namespace hemiroll::files {
namespace {

TEST(PrintableName, ValidUtf8IsShownAsItIs) {
  EXPECT_TRUE(isPrintableUtf8("trial-001.csv"));
  EXPECT_TRUE(isPrintableUtf8("Übung 3 — 試験 😀"));
  EXPECT_EQ(printable("Übung 3 — 試験 😀"), "Übung 3 — 試験 😀");
}

// Each byte that is not part of a valid, printable sequence becomes \xNN;
// the rest of the name is kept, so it still points at the file.
TEST(PrintableName, InvalidBytesAndControlsAreEscaped) {
  EXPECT_EQ(printable("a\xFF" "b"), "a\\xFFb");                  // never valid
  EXPECT_EQ(printable("\xC3"), "\\xC3");                          // a lead byte cut off
  EXPECT_EQ(printable("\xC0\xAF"), "\\xC0\\xAF");                 // overlong '/'
  EXPECT_EQ(printable("\xED\xA0\x80"), "\\xED\\xA0\\x80");        // a surrogate
  EXPECT_EQ(printable("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // past U+10FFFF
  EXPECT_EQ(printable("line\nbreak\t\x7F"), "line\\x0Abreak\\x09\\x7F");
  EXPECT_EQ(printable("\xC2\x85"), "\\xC2\\x85");                 // a C1 control
  for (const char* name : {"a\xFF" "b", "\xC3", "x\ny"}) EXPECT_FALSE(isPrintableUtf8(name)) << name;
  // Whatever the bytes, the result is valid and printable.
  std::string all;
  for (int b = 0; b < 256; ++b) all += static_cast<char>(b);
  EXPECT_TRUE(isPrintableUtf8(printable(all)));
}

TEST(PrintableName, ValidUtf8KeepsControlsForWritersThatEscapeThem) {
  EXPECT_EQ(validUtf8("a\xFF\nb\t"), "a\\xFF\nb\t");
  EXPECT_EQ(validUtf8("\xC3\xA4"), "\xC3\xA4");
}

}  // namespace
}  // namespace hemiroll::files
