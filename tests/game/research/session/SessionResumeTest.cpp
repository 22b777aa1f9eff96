// game/research/session/SessionResume: where an interrupted session goes on, and
// the interrupted trial's files moved aside, never deleted.

#include "game/research/session/SessionResume.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "engine/record/DurableFile.h"
#include "engine/record/RecordingSession.h"
#include "game/research/session/SessionError.h"
#include "game/research/session/SessionFolder.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::vector<ManifestTrial> plan(int trials) {
  std::vector<ManifestTrial> out;
  for (int i = 1; i <= trials; ++i) {
    ManifestTrial t;
    t.index = i;
    t.trialId = sessionTrialId(i);
    out.push_back(t);
  }
  return out;
}

class SessionResumeTest : public ::testing::Test {
 protected:
  // A trial as the session writes it: rows, the sidecar completed, then
  // (when `row`) its results row.
  void finished(int index, bool row = true) {
    record::TrialMeta meta;
    meta.trialId = sessionTrialId(index);
    record::TrialRecorder recorder = session_.beginTrial(meta);
    recorder.push(haptics::RecordRow{});
    record::TrialEnd end;
    end.outcome = "success";
    recorder.finish(end);
    if (row) session_.appendResult(record::RecordingSession::resultOf(recorder, end, 1.0));
  }
  // A trial a crash interrupted: its sidecar still says "complete": false.
  void interrupted(int index) {
    record::TrialMeta meta;
    meta.trialId = sessionTrialId(index);
    record::TrialRecorder recorder = session_.beginTrial(meta);
    recorder.push(haptics::RecordRow{});
  }
  std::string errorOf(int trials) const {
    try {
      findResumePoint(dir_.path(), plan(trials));
    } catch (const SessionError& e) {
      EXPECT_EQ(e.kind(), SessionError::Kind::Environment);
      return e.what();
    }
    return "no error";
  }

  test::TempDirectory dir_;
  record::RecordingSession session_{dir_.path(), {"p01", "1"}};
};

TEST_F(SessionResumeTest, AnEmptyFolderStartsAtTheFirstTrial) {
  const ResumePoint p = findResumePoint(dir_.path(), plan(3));
  EXPECT_EQ(p.done, 0);
  EXPECT_TRUE(p.interrupted.empty());
}

TEST_F(SessionResumeTest, FinishedTrialsAreKeptAndTheInterruptedOneIsFoundWithoutTouchingIt) {
  finished(1);
  finished(2);
  interrupted(3);
  const ResumePoint p = findResumePoint(dir_.path(), plan(4));
  EXPECT_EQ(p.done, 2);
  ASSERT_EQ(p.interrupted.size(), 1u);
  EXPECT_EQ(p.interrupted[0].first, "trial-003");
  EXPECT_EQ(p.interrupted[0].second, "interrupted before it finished");
  EXPECT_TRUE(fs::exists(dir_.path() / "trial-003.csv"));  // finding changes nothing
}

TEST_F(SessionResumeTest, ACompleteSidecarWithoutItsResultsRowRunsAgain) {
  finished(1);
  finished(2, /*row=*/false);
  const ResumePoint p = findResumePoint(dir_.path(), plan(2));
  EXPECT_EQ(p.done, 1);
  ASSERT_EQ(p.interrupted.size(), 1u);
  EXPECT_EQ(p.interrupted[0].second, "finished, but its results row was never written");
}

TEST_F(SessionResumeTest, MovingAsideRenamesEveryFileWithTheFirstFreeNumber) {
  finished(1);
  interrupted(2);
  record::writeFileAtomically(dir_.path() / "trial-002.replay", "log");
  const std::string csv = hemiroll::test::TempDirectory::read(dir_.path() / "trial-002.csv");
  const ManifestAborted first = moveTrialAside(dir_.path(), "trial-002", "interrupted before it finished");
  EXPECT_EQ(first.trialId, "trial-002");
  EXPECT_EQ(first.reason, "interrupted before it finished");
  const std::vector<std::pair<std::string, std::string>> moved = {{"trial-002.csv", "trial-002.csv.aborted-1"},
                                                                  {"trial-002.json", "trial-002.json.aborted-1"},
                                                                  {"trial-002.replay", "trial-002.replay.aborted-1"}};
  EXPECT_EQ(first.moved, moved);
  EXPECT_FALSE(fs::exists(dir_.path() / "trial-002.csv"));
  EXPECT_EQ(hemiroll::test::TempDirectory::read(dir_.path() / "trial-002.csv.aborted-1"), csv);  // moved, not rewritten
  // Interrupted again: the next number; the first set stays.
  interrupted(2);
  const ManifestAborted second = moveTrialAside(dir_.path(), "trial-002", "interrupted before it finished");
  ASSERT_EQ(second.moved.size(), 2u);
  EXPECT_EQ(second.moved[0].second, "trial-002.csv.aborted-2");
  EXPECT_TRUE(fs::exists(dir_.path() / "trial-002.replay.aborted-1"));
  EXPECT_TRUE(fs::exists(dir_.path() / "trial-001.csv"));
  EXPECT_EQ(findResumePoint(dir_.path(), plan(2)).done, 1);
  EXPECT_TRUE(findResumePoint(dir_.path(), plan(2)).interrupted.empty());
}

TEST_F(SessionResumeTest, AFolderChangedByHandIsRefused) {
  finished(1);
  fs::remove(dir_.path() / "trial-001.json");
  EXPECT_THAT(errorOf(2), HasSubstr("lists trial-001 but trial-001.json is missing or not complete"));
}

TEST_F(SessionResumeTest, AFinishedTrialAfterAnUnfinishedOneIsRefused) {
  finished(2);
  EXPECT_THAT(errorOf(3), HasSubstr("trial-002 is finished but trial-001 is not"));
}

TEST_F(SessionResumeTest, AResultsRowOutsideThePlanIsRefused) {
  finished(1);
  finished(2);
  EXPECT_THAT(errorOf(1), HasSubstr("lists trial 'trial-002', which is not in the session's plan"));
}

}  // namespace
}  // namespace hemiroll::game
