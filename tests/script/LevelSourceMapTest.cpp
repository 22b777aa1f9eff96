// engine/script/LevelSourceMap: the line of a field of the returned table,
// found from the source text.

#include "engine/script/LevelSourceMap.h"

#include <gtest/gtest.h>
#include <malloc.h>

#include <algorithm>
#include <string>

namespace hemiroll::script {
namespace {

constexpr const char* kLevel = R"(-- a comment with { braces } and name = 1
local helper = { name = "not this one" }   -- line 2
--[[ a long comment
     task = { } ]]
return {
  name = "the level",                      -- line 6
  description = [[a long
string with } and { inside]],              -- lines 7-8
  task = {                                 -- line 9
    stages = {
      { targets = { x_p = { value = 0, tol = 1 } } },   -- line 11
      {
        targets = {
          p = { value = { 0, 0 },          -- line 14
                tol = 0.1 },               -- line 15
        },
        hold = 2,                          -- line 17
      },
    },
  },
  callbacks = {
    on_update = function(s)
      local a, b = 1, 2                    -- commas inside a function body
      if a == b then x = { 1 } end
    end,
    rate = 20,                             -- line 26
  },
  ["medals"] = { gold = 3 },               -- line 28
}
)";

TEST(LevelSourceMap, FindsFieldsByPath) {
  const LevelSourceMap map(kLevel);
  EXPECT_EQ(map.lineOf("name"), 6);
  EXPECT_EQ(map.lineOf("task"), 9);
  EXPECT_EQ(map.lineOf("task.stages[1].targets.x_p"), 11);
  EXPECT_EQ(map.lineOf("task.stages[2].targets.p"), 14);
  EXPECT_EQ(map.lineOf("task.stages[2].targets.p.tol"), 15);
  EXPECT_EQ(map.lineOf("task.stages[2].hold"), 17);
  EXPECT_EQ(map.lineOf("callbacks.rate"), 26);
  EXPECT_EQ(map.lineOf("medals.gold"), 28);
}

TEST(LevelSourceMap, AnAbsentFieldGetsItsDeepestWrittenParent) {
  const LevelSourceMap map(kLevel);
  EXPECT_EQ(map.lineOf("task.stages[2].targets.p.value[3]"), 14);
  EXPECT_EQ(map.lineOf("task.time_limit"), 9);
  EXPECT_EQ(map.lineOf("nothing"), 5);  // the returned table
  EXPECT_EQ(map.lineOf(""), 5);
}

TEST(LevelSourceMap, FollowsAReturnedLocal) {
  const LevelSourceMap map("local level = {\n  name = 1,\n}\nlevel.extra = 2\nreturn level\n");
  EXPECT_EQ(map.lineOf("name"), 2);
  EXPECT_EQ(map.lineOf("extra"), 1);
}

TEST(LevelSourceMap, NeverFailsOnText) {
  for (const char* text : {"", "return", "return {", "}}}}", "return { a = { b = ", "\"unterminated", "[==[ open",
                           "return {{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{"}) {
    const LevelSourceMap map(text);
    EXPECT_GE(map.lineOf("a.b.c"), 1) << text;
  }
}

// A "\z" escape skips the white space after it, line breaks included; the
// map counted none of those lines and every later field was a line short,
// then line 1 (issue 33). A backslash before a line break is a line too.
TEST(LevelSourceMap, EscapedLineBreaksInStringsAreCounted) {
  const LevelSourceMap map(
      "return {\n"
      "  description = \"one \\z\n"
      "      two \\z\n\n"
      "      three\",\n"                // the string ends on line 5
      "  note = 'a\\\nb',\n"            // a backslash-newline: lines 6-7
      "  time_limit = 1e16,\n"          // line 8
      "}\n");
  EXPECT_EQ(map.lineOf("description"), 2);
  EXPECT_EQ(map.lineOf("note"), 6);
  EXPECT_EQ(map.lineOf("time_limit"), 8);
}

// The map's cost is bounded whatever the text (issue 33: a 4 MiB protocol of
// a million tables cost 275 MB while its error's line was looked up): it
// stops reading and building at its caps and answers a line all the same.
TEST(LevelSourceMap, APathologicalFileCostsBoundedMemory) {
  std::string text = "local t = {";
  for (int i = 0; i < 1'300'000; ++i) text += "{},";
  text += "}\nreturn { name = 1 }\n";  // 3.9 MB
  const struct mallinfo2 before = mallinfo2();
  const LevelSourceMap map(text);
  const struct mallinfo2 after = mallinfo2();
  EXPECT_GE(map.lineOf("name"), 1);
  // What the map keeps: at most 100 000 tables and 500 000 fields.
  EXPECT_LT(after.uordblks - std::min(after.uordblks, before.uordblks), std::size_t{64} << 20);
}

}  // namespace
}  // namespace hemiroll::script
