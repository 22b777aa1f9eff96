// game/research/sweep/SweepSpecJson: the canonical spec and its hash - the same text
// back after a round trip, a new hash for any change that decides a row, the
// same hash for a new description.

#include "game/research/sweep/SweepSpecJson.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "game/research/sweep/SweepError.h"
#include "tests/game/support/TinySweep.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

TEST(SweepSpecJson, RoundTripsToTheSameText) {
  const task::SweepDef d = test::sweepOf(R"(return { start = "rest", tol = 1e-9, analysis = { min_rate = 0.01 },
      axes = { { param = "m_p", range = { from = 0.1, to = 3, count = 4, log = true } },
               { param = "Omega", values = { -0.3141592653589793, -0.1 } } } })");
  const std::string text = specJson(d);
  const task::SweepDef back = specFromJson(text, "x");
  EXPECT_EQ(specJson(back), text);
  EXPECT_EQ(back.start, task::SweepStart::Rest);
  EXPECT_EQ(back.analysis.minRate, 0.01);
  EXPECT_EQ(back.axes[0].values, d.axes[0].values);  // bit for bit
  EXPECT_TRUE(back.axes[0].log);
  EXPECT_THAT(specHash(d), StartsWith("fnv1a-"));
  EXPECT_EQ(specHash(d).size(), 6u + 16u);
}

TEST(SweepSpecJson, TheHashFollowsWhatDecidesTheRows) {
  const std::string base = R"(return { description = "%s", duration = %s, axes = { { param = "k", values = { 6, 8 } } } })";
  auto spec = [&](const char* description, const char* duration) {
    std::string s = base;
    s.replace(s.find("%s"), 2, description);
    s.replace(s.find("%s"), 2, duration);
    return test::sweepOf(s);
  };
  EXPECT_EQ(specHash(spec("a", "10")), specHash(spec("b", "10")));
  EXPECT_NE(specHash(spec("a", "10")), specHash(spec("a", "10.5")));
  task::SweepDef d = spec("a", "10");
  const std::string before = specHash(d);
  d.axes[0].values[1] = std::nextafter(8.0, 9.0);  // one bit
  EXPECT_NE(specHash(d), before);
}

TEST(SweepSpecJson, RefusesWhatIsNotASpec) {
  for (const char* text : {"", "{}", "[1]", R"({"params": 3})"}) {
    try {
      specFromJson(text, "m.json");
      FAIL() << text;
    } catch (const SweepError& e) {
      EXPECT_EQ(e.kind(), SweepError::Kind::BadInput);
      EXPECT_THAT(e.what(), StartsWith("m.json: not a sweep spec ("));
    }
  }
}

}  // namespace
}  // namespace hemiroll::game
