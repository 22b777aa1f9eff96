// game/research/sweep/SweepManifest: the manifest both ways, and refused when it is
// not one or its spec no longer matches its hash.

#include "game/research/sweep/SweepManifest.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "game/research/sweep/SweepError.h"
#include "game/research/sweep/SweepSpecJson.h"
#include "tests/game/support/TinySweep.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

SweepManifest sample() {
  const task::SweepDef d = test::sweepOf(test::kTinySweep);
  SweepManifest m;
  m.program = "hemiroll 9";
  m.specFile = "a/b.lua";
  m.description = "say \"hi\"";
  m.specHash = specHash(d);
  m.specJson = specJson(d);
  m.pointsTotal = 9;
  m.shard = {1, 4};
  m.pointCount = 2;
  m.csv = "part-1-of-4.csv";
  m.complete = true;
  m.threads = 3;
  m.wallSeconds = 1.5;
  m.resumedPoints = 1;
  return m;
}

TEST(SweepManifest, RoundTrips) {
  const SweepManifest m = sample();
  const SweepManifest back = parseManifest(manifestJson(m), "m.json");
  EXPECT_EQ(back.program, m.program);
  EXPECT_EQ(back.specFile, m.specFile);
  EXPECT_EQ(back.description, m.description);
  EXPECT_EQ(back.specHash, m.specHash);
  EXPECT_EQ(back.specJson, m.specJson);
  EXPECT_EQ(back.pointsTotal, 9);
  EXPECT_EQ(back.shard.index, 1);
  EXPECT_EQ(back.shard.count, 4);
  EXPECT_EQ(back.pointCount, 2);
  EXPECT_EQ(back.csv, m.csv);
  EXPECT_TRUE(back.complete);
  EXPECT_EQ(back.threads, 3);
  EXPECT_EQ(back.wallSeconds, 1.5);
  EXPECT_EQ(back.resumedPoints, 1);
  EXPECT_EQ(manifestJson(back), manifestJson(m));
}

std::string errorOf(const std::string& text) {
  try {
    parseManifest(text, "m.json");
  } catch (const SweepError& e) {
    EXPECT_EQ(e.kind(), SweepError::Kind::BadInput);
    return e.what();
  }
  return "no error";
}

TEST(SweepManifest, RefusesWhatIsNotOneOfOurs) {
  const std::string good = manifestJson(sample());
  EXPECT_THAT(errorOf("{"), HasSubstr("m.json: not a sweep manifest"));
  std::string other = good;
  other.replace(other.find("hemiroll-sweep-1"), 16, "hemiroll-sweep-9");
  EXPECT_THAT(errorOf(other), HasSubstr("format 'hemiroll-sweep-9'"));
  std::string counted = good;
  counted.replace(counted.find("\"count\": 2"), 10, "\"count\": 3");
  EXPECT_THAT(errorOf(counted), HasSubstr("its shard and points do not agree"));
  std::string edited = good;
  edited.replace(edited.find("\"duration_s\": 12.0"), 18, "\"duration_s\": 13.0");
  EXPECT_THAT(errorOf(edited), HasSubstr("m.json: its spec does not match its spec_hash"));
}

}  // namespace
}  // namespace hemiroll::game
