// engine/script/LuaPatternBound: repeated items counted as Lua's matcher
// sees them, and the bound's recurrence written out by hand for small
// patterns; the search the red team found (issue 33) is over the bound.

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

// W(m) by hand (LuaPatternBound.h): "b*" from m characters costs a scan of
// m+1 and the end (1) from each of its m+1 lengths: 2 (m+1); "a*" before it
// (m+1) + sum_j 2 (j+1) = (m+1) + (m+1)(m+2). At m = 10: 11 + 132 = 143.
TEST(LuaPatternBound, FollowsTheMatcherItemByItem) {
  EXPECT_DOUBLE_EQ(patternStepBound("^a*b*", 10, PatternUse::FindOrMatch), 143.0);
  // Unanchored: from each of the n + 1 starts.
  EXPECT_DOUBLE_EQ(patternStepBound("a*b*", 10, PatternUse::FindOrMatch), 11.0 * 143.0);
  // gmatch and gsub try each start at most twice; gmatch reads '^' as a character.
  EXPECT_DOUBLE_EQ(patternStepBound("^a*b*", 10, PatternUse::Gmatch), 22.0 * (1.0 + 143.0));
  EXPECT_DOUBLE_EQ(patternStepBound("^a*b*", 10, PatternUse::Gsub), 143.0);
  // No repeats: each class once, then the end.
  EXPECT_DOUBLE_EQ(patternStepBound("abc", 100, PatternUse::FindOrMatch), 101.0 * 4.0);
  // A set costs its text; '?' tries the rest with it and without.
  EXPECT_DOUBLE_EQ(patternStepBound("^[abc]x", 100, PatternUse::FindOrMatch), 5.0 + 1.0 + 1.0);
  EXPECT_DOUBLE_EQ(patternStepBound("^a?", 10, PatternUse::FindOrMatch), 1.0 + 2.0 * 1.0);
  // %b scans to the end of the subject: (m+1) + 1 + the end's 1.
  EXPECT_DOUBLE_EQ(patternStepBound("^%b()", 10, PatternUse::FindOrMatch), 13.0);
}

// s:find(".-%b()") on 5 000 '(' passed the old bound (5e7) and ran for 9 s:
// every length of ".-" is followed by a scan of %b to the end, n^3 / 6 in
// all. The bound is now 3 (n+1) + C(n+2, 2) per start: 6.3e10.
TEST(LuaPatternBound, ABalanceAfterARepeatIsCubic) {
  const double n = 5000.0;
  EXPECT_DOUBLE_EQ(patternStepBound(".-%b()", 5000, PatternUse::FindOrMatch),
                   (n + 1.0) * (3.0 * (n + 1.0) + (n + 2.0) * (n + 1.0) / 2.0));
  EXPECT_GT(patternStepBound(".-%b()", 5000, PatternUse::FindOrMatch), 2e8);
  // "%b()" alone is quadratic: 14 000 characters stay under 2e8 (0.13 s).
  EXPECT_LT(patternStepBound("%b()", 14000, PatternUse::FindOrMatch), 2e8);
}

TEST(LuaPatternBound, MalformedPatternsAndOverflowAreHandled) {
  EXPECT_DOUBLE_EQ(patternStepBound("[abc", 1000, PatternUse::FindOrMatch), 4.0);  // Lua refuses it at once
  EXPECT_DOUBLE_EQ(patternStepBound("%", 1000, PatternUse::FindOrMatch), 1.0);
  // Forty repeats on a megabyte: far past a double's range of integers, not NaN.
  const double huge = patternStepBound(std::string(80, '.').replace(1, 78, std::string(39, '.') + std::string(39, '-')),
                                       1 << 20, PatternUse::FindOrMatch);
  EXPECT_GT(huge, 1e100);
}

}  // namespace
}  // namespace hemiroll::script
