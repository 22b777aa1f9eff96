// game/research/session/SessionLock: one session at a time in a folder (issue 33),
// a stale record taken over with a note, a clean release leaving none. Two
// processes and a killed holder: SessionCommandTest.

#include "game/research/session/SessionLock.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "game/research/session/SessionError.h"
#include "tests/support/ErrorMessage.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

TEST(SessionLockTest, ASecondHolderIsRefusedNamingTheFirst) {
  const test::TempDirectory dir;
  const SessionLock first(dir.path(), "test one");
  EXPECT_EQ(first.note(), "");
  const std::string error = test::messageOf<SessionError>([&] { SessionLock second(dir.path(), "test two"); });
  EXPECT_THAT(error, HasSubstr(dir.path().string() + " is in use by another session (process " +
                               std::to_string(getpid()) + " on "));
  EXPECT_THAT(error, HasSubstr(", test one, since "));
}

TEST(SessionLockTest, AReleasedLockIsTakenAgainWithoutANote) {
  const test::TempDirectory dir;
  { const SessionLock first(dir.path(), "test one"); }
  const SessionLock again(dir.path(), "test two");
  EXPECT_EQ(again.note(), "");
  EXPECT_THAT(test::TempDirectory::read(dir.path() / kLockFile), HasSubstr(", test two, since "));
}

// A holder that died left its record but not its lock (the kernel released
// it): the next session takes over and says so.
TEST(SessionLockTest, AStaleRecordIsTakenOverWithANote) {
  const test::TempDirectory dir;
  dir.write(kLockFile, "process 999999 on elsewhere, hemiroll session of x as bot, since 2024-01-01T00:00:00Z\n");
  const SessionLock lock(dir.path(), "test");
  EXPECT_THAT(lock.note(), HasSubstr("took over the session folder's lock from a session that ended without "
                                     "releasing it (process 999999 on elsewhere"));
}

TEST(SessionLockTest, ALockFileThatIsNotAFileIsRefused) {
  const test::TempDirectory dir;
  ASSERT_EQ(mkfifo((dir.path() / kLockFile).c_str(), 0600), 0);
  EXPECT_THAT(test::messageOf<SessionError>([&] { SessionLock lock(dir.path(), "test"); }),
              HasSubstr("is not a regular file"));
}

}  // namespace
}  // namespace hemiroll::game
