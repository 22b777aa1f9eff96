// game/research/session/SessionBotMemory: the simulated participant's memory in
// the session folder - restored after the last finished trial, the memory
// before a trial that must run again, refused when it contradicts the
// trials done; script::BotMemory's cap and names.

#include "game/research/session/SessionBotMemory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "engine/script/ScriptError.h"
#include "game/research/session/SessionError.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

script::BotMemory practised(double trials) {
  script::BotMemory m;
  m.set("practice_trials", trials);
  return m;
}

TEST(SessionBotMemoryTest, ResumeRestoresTheMemoryAfterTheLastFinishedTrial) {
  test::TempDirectory dir;
  std::string note;
  EXPECT_TRUE(restoreBotMemory(dir.path(), 0, note).empty());  // a new session
  EXPECT_EQ(note, "");
  writeBotMemory(dir.path(), 3, practised(3), practised(2));
  EXPECT_EQ(restoreBotMemory(dir.path(), 3, note).get("practice_trials"), 3.0);
  // Trial 3's results row never written: it runs again, from the memory it began with.
  EXPECT_EQ(restoreBotMemory(dir.path(), 2, note).get("practice_trials"), 2.0);
  try {
    (void)restoreBotMemory(dir.path(), 5, note);
    FAIL() << "no error";
  } catch (const SessionError& e) {
    EXPECT_EQ(e.kind(), SessionError::Kind::Environment);
    EXPECT_THAT(e.what(), HasSubstr("holds the memory after trial 3, but 5 trials are done"));
  }
}

TEST(SessionBotMemoryTest, ASessionWithoutAMemoryGoesOnWithAnEmptyOneAndSaysSo) {
  test::TempDirectory dir;
  std::string note;
  EXPECT_TRUE(restoreBotMemory(dir.path(), 4, note).empty());
  EXPECT_THAT(note, HasSubstr("kept no bot memory before"));
  dir.write(kBotMemoryFile, "{ not json");
  EXPECT_THROW((void)restoreBotMemory(dir.path(), 4, note), SessionError);
  dir.write(kBotMemoryFile,
            R"({"format":"hemiroll-bot-memory","format_version":1,"after_trial":4,"memory":{"Bad Name":1},"before":{}})");
  try {
    (void)restoreBotMemory(dir.path(), 4, note);
    FAIL() << "no error";
  } catch (const SessionError& e) {
    EXPECT_THAT(e.what(), HasSubstr("a memory entry's name is made of a-z, 0-9 and '_' ('Bad Name' is not)"));
  }
}

TEST(SessionBotMemoryTest, TheMemoryIsCappedAndHoldsFiniteNumbersUnderPlainNames) {
  script::BotMemory m;
  for (std::size_t i = 0; i < script::BotMemory::kMaxEntries; ++i) {
    std::string name = "k";  // appended, not "k" + ...: GCC 12 warns falsely (-Wrestrict) on that
    name += std::to_string(i);
    m.set(name, 1.0);
  }
  m.set("k0", 2.0);  // changing an entry is always allowed
  EXPECT_EQ(m.get("k0"), 2.0);
  EXPECT_THROW(m.set("one_more", 1.0), script::ScriptError);
  EXPECT_THROW(m.set("k1", std::nan("")), script::ScriptError);
  EXPECT_THROW(m.set(std::string(33, 'a'), 1.0), script::ScriptError);
  EXPECT_FALSE(m.get("absent"));
}

}  // namespace
}  // namespace hemiroll::game
