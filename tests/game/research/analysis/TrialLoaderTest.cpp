// game/research/analysis TrialLoader: recordings, session folders and sim CSVs as
// trials; interrupted recordings with a note; broken input named.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "game/research/analysis/AnalysisInputError.h"
#include "game/research/analysis/TrialLoader.h"
#include "tests/analysis/support/Synthetic.h"
#include "tests/game/support/RoseRecording.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

std::string errorOf(const std::vector<std::string>& paths) {
  try {
    loadTrials(paths);
  } catch (const AnalysisInputError& e) {
    return e.what();
  }
  return "";
}

TEST(TrialLoader, ARecordingGivesItsColumns) {
  const test::TempDirectory dir;
  const fs::path csv = test::writeRoseRecording(dir.path(), "trial-001", 200, true);
  const std::vector<TrialData> trials = loadTrials({csv.string()});
  ASSERT_EQ(trials.size(), 1u);
  const TrialData& t = trials[0];
  EXPECT_EQ(t.id, "trial-001");
  EXPECT_EQ(t.kind, "recording");
  ASSERT_EQ(t.time.size(), 200u);
  const test::Planar rose = test::rose(0.015, 0.008, 8, -M_PI / 10, 1.99, 100.0);
  EXPECT_DOUBLE_EQ(t.massX[17], rose.x[17]);  // bit for bit through the CSV
  EXPECT_DOUBLE_EQ(t.massY[17], rose.y[17]);
  EXPECT_DOUBLE_EQ(t.psi[17], -0.1 * t.time[17]);
  EXPECT_TRUE(t.notes.empty());
}

TEST(TrialLoader, ASessionFolderGivesItsTrialsInNameOrder) {
  const test::TempDirectory dir;
  test::writeRoseRecording(dir.path(), "b-trial", 50, true);
  test::writeRoseRecording(dir.path(), "a-trial", 50, true);
  std::ofstream(dir.path() / "results.csv") << "participant,session\n";
  std::ofstream(dir.path() / "analysis.csv") << "trial,source\n";
  const std::vector<TrialData> trials = loadTrials({dir.path().string()});
  ASSERT_EQ(trials.size(), 2u);
  EXPECT_EQ(trials[0].id, "a-trial");
  EXPECT_EQ(trials[1].id, "b-trial");
}

TEST(TrialLoader, AnInterruptedRecordingIsReadWithANote) {
  const test::TempDirectory dir;
  const fs::path csv = test::writeRoseRecording(dir.path(), "cut", 100, false);
  std::ofstream(csv, std::ios::app) << "1.01,101,0.0";  // killed mid-row
  const std::vector<TrialData> trials = loadTrials({csv.string()});
  ASSERT_EQ(trials.size(), 1u);
  EXPECT_EQ(trials[0].time.size(), 100u);
  ASSERT_EQ(trials[0].notes.size(), 1u);
  EXPECT_THAT(trials[0].notes[0], HasSubstr("interrupted"));
}

TEST(TrialLoader, TheSameFileTwiceGetsTwoIds) {
  const test::TempDirectory dir;
  const std::string csv = test::writeRoseRecording(dir.path(), "t", 50, true).string();
  const std::vector<TrialData> trials = loadTrials({csv, csv});
  ASSERT_EQ(trials.size(), 2u);
  EXPECT_EQ(trials[1].id, "t-2");
}

TEST(TrialLoader, BrokenInputIsNamedWithFileAndLine) {
  const test::TempDirectory dir;
  const fs::path csv = test::writeRoseRecording(dir.path(), "bad", 50, true);
  std::string text = hemiroll::test::TempDirectory::read(csv);
  // Line 5 (the fourth row): its x_p (column 3) becomes text.
  std::size_t at = 0;
  for (int line = 1; line < 5; ++line) at = text.find('\n', at) + 1;
  const std::size_t field = text.find(',', text.find(',', at) + 1) + 1;
  text.replace(field, text.find(',', field) - field, "oops");
  std::ofstream(csv, std::ios::trunc) << text;
  EXPECT_THAT(errorOf({csv.string()}), HasSubstr("bad.csv: line 5: column 3"));

  fs::remove(dir.path() / "bad.json");
  EXPECT_THAT(errorOf({csv.string()}), HasSubstr("bad.json"));
  EXPECT_THAT(errorOf({dir.write("other.csv", "a,b,c\n1,2,3\n")}), HasSubstr("other.csv:1: neither a trial recording"));
  EXPECT_THAT(errorOf({(dir.path() / "nowhere.csv").string()}), HasSubstr("nowhere.csv: no such file or folder"));
  const test::TempDirectory empty;
  EXPECT_THAT(errorOf({empty.path().string()}), HasSubstr("holds no trial CSV"));
}

}  // namespace
}  // namespace hemiroll::game
