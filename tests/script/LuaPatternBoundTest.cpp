// engine/script/LuaPatternBound: repeated items counted as Lua's matcher
// sees them, and the bound's combinatorics written out.

#include "engine/script/LuaPatternBound.h"

#include <gtest/gtest.h>

namespace hemiroll::script {
namespace {

TEST(LuaPatternBound, CountsRepeatedItemsNotEscapesOrSetMembers) {
  EXPECT_EQ(repeatedItems("abc"), 0);
  EXPECT_EQ(repeatedItems(".-.-.-.-.-b"), 5);
  EXPECT_EQ(repeatedItems("^(%w+)%s*=%s*(.-)$"), 4);
  EXPECT_EQ(repeatedItems("%*%+%-"), 0);       // escaped: literal characters
  EXPECT_EQ(repeatedItems("[*+-]"), 0);         // members of a set
  EXPECT_EQ(repeatedItems("[]*]+"), 1);         // ']' first is a member; the set repeats
  EXPECT_EQ(repeatedItems("%b()*"), 0);         // %b takes its two characters; '*' is literal after it
  EXPECT_EQ(repeatedItems("%f[%w]%w+"), 1);
  EXPECT_EQ(repeatedItems("a?b?"), 2);
}

TEST(LuaPatternBound, IsStartsTimesTheWaysToShareTheSubject) {
  // q = 2 on n = 10: C(12, 2) = 66 ways, plus 10 steps, from each of 11 starts.
  EXPECT_DOUBLE_EQ(patternStepBound("a*b*", 10, true), 11.0 * (66.0 + 10.0));
  // Anchored: one start.
  EXPECT_DOUBLE_EQ(patternStepBound("^a*b*", 10, true), 66.0 + 10.0);
  // gmatch ignores '^' as an anchor: every start again.
  EXPECT_DOUBLE_EQ(patternStepBound("^a*b*", 10, false), 11.0 * (66.0 + 10.0));
  // No repeats: linear per start.
  EXPECT_DOUBLE_EQ(patternStepBound("abc", 100, true), 101.0 * (1.0 + 100.0));
}

}  // namespace
}  // namespace hemiroll::script
