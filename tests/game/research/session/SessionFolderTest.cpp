// game/research/session/SessionFolder: where a session's data goes and the ids that
// name its folders.

#include "game/research/session/SessionFolder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

TEST(SessionFolder, DataRootExperimentParticipantSession) {
  EXPECT_EQ(sessionFolder("/data", "exp", "p01", "2"), std::filesystem::path("/data/exp/p01/2"));
}

TEST(SessionFolder, TheDefaultRootIsUnderTheGamesDataDirectory) {
  const char* before = std::getenv("HEMIROLL_DATA_DIR");
  const std::string saved = before ? before : "";
  setenv("HEMIROLL_DATA_DIR", "/somewhere", 1);
  EXPECT_EQ(defaultSessionsRoot(), std::filesystem::path("/somewhere/sessions"));
  if (before) setenv("HEMIROLL_DATA_DIR", saved.c_str(), 1);
  else unsetenv("HEMIROLL_DATA_DIR");
}

TEST(SessionFolder, IdsThatCannotNameAFolderAreRefusedInOneSentence) {
  EXPECT_EQ(checkFolderId("p01", "participant id"), "");
  EXPECT_EQ(checkFolderId("../etc", "participant id"),
            "the participant id '../etc' must be 1 to 64 letters, digits, '-' or '_' (it names a folder)");
  EXPECT_THAT(checkFolderId("", "session id"), HasSubstr("the session id '' must be"));
  EXPECT_THAT(checkFolderId("a b", "session id"), HasSubstr("must be"));
}

TEST(SessionFolder, TrialIdsSortInPlanOrder) {
  EXPECT_EQ(sessionTrialId(1), "trial-001");
  EXPECT_EQ(sessionTrialId(36), "trial-036");
  EXPECT_EQ(sessionTrialId(1234), "trial-1234");
  EXPECT_LT(sessionTrialId(9), sessionTrialId(10));
}

}  // namespace
}  // namespace hemiroll::game
