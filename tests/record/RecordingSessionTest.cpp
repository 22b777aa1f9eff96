#include "engine/record/RecordingSession.h"

#include <gtest/gtest.h>

#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/record/RecordingReader.h"
#include "tests/record/support/RecordRows.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::record {
namespace {

TEST(RecordingSessionTest, TrialsAndResultsCarryTheSessionIds) {
  hemiroll::test::TempDirectory dir;
  const RecordingSession session(dir.path() / "p07" / "s3", {"p07", "s3"});
  for (const char* id : {"trial-001", "trial-002"}) {
    TrialMeta meta;
    meta.trialId = id;
    meta.levelName = "slalom";
    TrialRecorder rec = session.beginTrial(meta);
    for (const auto& row : test::randomRows(4, 1)) rec.push(row);
    TrialEnd end;
    end.outcome = "failure";
    rec.finish(end);
    ResultsRow r = RecordingSession::resultOf(rec, end, 1.5);
    r.score = 2.0;
    session.appendResult(r);
  }
  const Recording r = RecordingReader::load(session.dir() / "trial-002.csv");
  EXPECT_EQ(r.meta.participant, "p07");
  EXPECT_EQ(r.meta.session, "s3");
  const std::string results = hemiroll::test::TempDirectory::read(session.resultsPath());
  EXPECT_EQ(std::count(results.begin(), results.end(), '\n'), 3);
  EXPECT_NE(results.find("p07,s3,trial-002,slalom,,failure,,1.5,2,4,0,"), std::string::npos) << results;
  EXPECT_EQ(session.replayPath("trial-002"), session.dir() / "trial-002.replay");
}

TEST(RecordingSessionTest, AFolderThatCannotBeMadeIsNamed) {
  hemiroll::test::TempDirectory dir;
  const std::string file = dir.write("plain-file", "x");
  try {
    RecordingSession session(std::filesystem::path(file) / "sub", {});
    FAIL() << "no error";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("plain-file/sub: cannot create the session folder"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace hemiroll::record
