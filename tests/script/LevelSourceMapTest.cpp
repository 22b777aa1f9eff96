// engine/script/LevelSourceMap: the line of a field of the returned table,
// found from the source text.

#include "engine/script/LevelSourceMap.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace hemiroll::script
