// game/research/session/SessionManifest: session.json both ways, and a broken one
// refused with the file's name.

#include "game/research/session/SessionManifest.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

SessionManifest sample() {
  SessionManifest m;
  m.experiment = "exp";
  m.description = "a \"quoted\" description";
  m.protocolFile = "levels/protocols/p.lua";
  m.protocolHash = "fnv1a-0123456789abcdef";
  m.protocolVersion = "2";
  m.participant = "p01";
  m.session = "1";
  m.seed = 9223372036854775807ULL;
  m.startTime = "2026-11-23T10:00:00.000Z";
  m.softwareVersion = "0.1.0";
  m.sittings = {{"2026-11-23T10:00:00.000Z", "0.1.0", 1, "mouse"}, {"2026-11-24T09:00:00.000Z", "0.1.1", 4, "bot.lua"}};
  ManifestTrial t;
  t.index = 1;
  t.trialId = "trial-001";
  t.block = 2;
  t.blockName = "assessment";
  t.trialInBlock = 3;
  t.repetition = 2;
  t.condition = 5;
  t.conditionLabel = "M3 alpha 1.5";
  t.levelFile = "levels/paper_reaching.lua";
  t.levelName = "The paper's reaching task";
  t.levelHash = "fnv1a-fedcba9876543210";
  t.method = "M3";
  t.stiffness = 250.0;
  t.damping = 10.0;
  t.alpha = 0.1 + 0.2;  // not a short decimal: must come back with the same bits
  t.timeLimit = 240.0;
  t.seed = 12345678901234567ULL;
  m.plan.push_back(t);
  t.index = 2;
  t.trialId = "trial-002";
  t.breakBefore = ManifestBreak{"rest", 60.0, true};
  m.plan.push_back(t);
  m.aborted.push_back({"trial-002", "2026-11-23T10:05:00.000Z", "interrupted before it finished",
                       {{"trial-002.csv", "trial-002.csv.aborted-1"}, {"trial-002.json", "trial-002.json.aborted-1"}}});
  return m;
}

TEST(SessionManifest, RoundTripsEveryField) {
  const SessionManifest m = sample();
  const SessionManifest back = SessionManifest::fromJson(m.toJson(), "session.json");
  EXPECT_EQ(back.toJson(), m.toJson());
  EXPECT_EQ(back.seed, m.seed);
  ASSERT_EQ(back.plan.size(), 2u);
  EXPECT_EQ(back.plan[0].alpha, 0.1 + 0.2);
  EXPECT_FALSE(back.plan[0].breakBefore);
  ASSERT_TRUE(back.plan[1].breakBefore);
  EXPECT_TRUE(back.plan[1].breakBefore->stop);
  EXPECT_EQ(back.sittings[1].firstTrial, 4);
  ASSERT_EQ(back.aborted.size(), 1u);
  EXPECT_EQ(back.aborted[0].moved[1].second, "trial-002.json.aborted-1");
}

TEST(SessionManifest, InvalidUtf8FromTheProtocolIsReplacedNotThrown) {
  SessionManifest m = sample();
  m.description = "bad \xff byte";
  m.plan[0].blockName = "\xc3(";
  std::string json;
  ASSERT_NO_THROW(json = m.toJson());
  const SessionManifest back = SessionManifest::fromJson(json, "session.json");
  EXPECT_EQ(back.description, "bad \xef\xbf\xbd byte");
  EXPECT_EQ(back.plan[0].blockName, "\xef\xbf\xbd(");
}

TEST(SessionManifest, KeysCarryTheirUnits) {
  const std::string json = sample().toJson();
  for (const char* key : {"\"kr_N_per_m\"", "\"kv_N_s_per_m\"", "\"time_limit_s\"", "\"min_duration_s\"",
                          "\"format\": \"hemiroll-session\""})
    EXPECT_THAT(json, HasSubstr(key));
}

TEST(SessionManifest, ABrokenOrForeignFileIsRefusedNamingIt) {
  const std::string good = sample().toJson();
  const std::pair<std::string, std::string> cases[] = {
      {good.substr(0, good.size() / 2), "session.json: not a readable session manifest"},
      {"{\"format\": \"hemiroll-trial\", \"format_version\": 1}", "session.json: not a session manifest"},
      {"[]", "session.json: not a readable session manifest"},
  };
  for (const auto& [text, expected] : cases) {
    try {
      SessionManifest::fromJson(text, "session.json");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const std::runtime_error& e) {
      EXPECT_THAT(e.what(), HasSubstr(expected));
    }
  }
  std::string newer = good;
  newer.replace(newer.find("\"format_version\": 1"), 19, "\"format_version\": 9");
  try {
    SessionManifest::fromJson(newer, "session.json");
    ADD_FAILURE() << "accepted a newer version";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("session.json: format version 9 (this program reads 1)"));
  }
}

}  // namespace
}  // namespace hemiroll::game
