// game/research/analysis/ExperimentTable: a small synthetic experiment folder (two
// participants in two groups, sessions written by ResearchSession with
// made-up results) read into one long table: a row per trial with its
// place, outcome and time, the measures and the movement columns; the
// numbers checked against the made-up ones and the curves against a mean
// worked out here.

#include "game/research/analysis/ExperimentTable.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "engine/record/ResultsFile.h"
#include "game/research/analysis/AnalysisInputError.h"
#include "game/research/analysis/LearningCurves.h"
#include "game/research/session/ResearchSession.h"
#include "game/trial/TrialSetup.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const std::string kLevels = std::string(HEMIROLL_SOURCE_DIR) + "/levels";

constexpr const char* kProtocol = R"lua(
return {
  experiment = "synthetic",
  groups = { { name = "guided", changes = { { block = "train", guidance = { kind = "autopilot", stiffness = 300 } } } },
             { name = "control" } },
  blocks = {
    { name = "train", level = "tutorial_01_tilt_and_return.lua", repetitions = 2 },
    { name = "test", level = "tutorial_01_tilt_and_return.lua" },
  },
}
)lua";

// Participant `id`'s three trials, ended as `times` (a time under 5 s a success).
void runParticipant(const test::TempDirectory& dir, const std::string& protocol, const std::string& id,
                    const std::vector<double>& times) {
  SessionRequest request;
  request.protocolPath = protocol;
  request.levelsDir = kLevels;
  request.participant = id;
  request.dataRoot = dir.path() / "data";
  ResearchSession s(request);
  s.begin("made-up");
  for (const double time : times) {
    const script::LoadedLevel level = s.loadNextLevel();
    auto recording = s.recordNext(level.def, trialLoopDef(level.def), "bot", botDeviceSpec());
    TrialResult result;
    result.outcome = time < 5.0 ? task::TrialOutcome::Success : task::TrialOutcome::Failure;
    result.reason = time < 5.0 ? "target held" : "time limit";
    result.time = time;
    result.ticks = static_cast<long long>(time * 1000.0);
    s.finishNext(*recording, result);
  }
}

TEST(ExperimentTableTest, OneRowPerTrialWithItsPlaceOutcomeTimeAndMeasures) {
  test::TempDirectory dir;
  const std::string protocol = dir.write("p.lua", kProtocol);
  runParticipant(dir, protocol, "p1", {9.0, 4.0, 3.0});   // the first to arrive: guided
  runParticipant(dir, protocol, "p2", {8.0, 7.0, 2.5});   // the second: control
  const fs::path experiment = dir.path() / "data" / "synthetic";
  EXPECT_TRUE(isExperimentFolder(experiment));
  EXPECT_FALSE(isExperimentFolder(experiment / "p1" / "1"));  // a session folder is analysed as trials
  const ExperimentTable table = readExperiment(experiment);
  EXPECT_EQ(table.sessions, 2);
  ASSERT_EQ(table.rows.size(), 6u);
  const auto column = [&](const std::string& name) {
    const auto at = std::find(table.columns.begin(), table.columns.end(), name);
    EXPECT_NE(at, table.columns.end()) << name;
    return static_cast<std::size_t>(at - table.columns.begin());
  };
  for (const char* name : {"participant", "group", "block", "block_name", "condition", "condition_label",
                           "trial_in_block", "outcome", "success", "time_s", "stages_passed", "contact_path_m",
                           "effort_N2_s", "final_margin", "guidance", "guidance_fade", "movement_steady_rate_rad_per_s",
                           "movement_notes"})
    (void)column(name);
  EXPECT_EQ(std::count(table.columns.begin(), table.columns.end(), "duration_s"), 0);  // it is time_s here
  const std::vector<std::string>& first = table.rows[0];
  EXPECT_EQ(first[column("participant")], "p1");
  EXPECT_EQ(first[column("group")], "guided");
  EXPECT_EQ(first[column("guidance")], "autopilot");
  EXPECT_EQ(first[column("time_s")], "9");
  EXPECT_EQ(first[column("outcome")], "failure");
  EXPECT_EQ(first[column("success")], "0");
  const std::vector<std::string>& last = table.rows[5];
  EXPECT_EQ(last[column("participant")], "p2");
  EXPECT_EQ(last[column("group")], "control");
  EXPECT_EQ(last[column("block_name")], "test");
  EXPECT_EQ(last[column("trial_in_block")], "1");
  EXPECT_EQ(last[column("time_s")], "2.5");
  EXPECT_EQ(last[column("success")], "1");
  EXPECT_EQ(last[column("guidance")], "none");
  for (const auto& row : table.rows) EXPECT_EQ(row.size(), table.columns.size());
  // The made-up trials have no samples: their rows stay, with a note each.
  EXPECT_EQ(table.notes.size(), 6u);
  // The CSV reads back as the same table (one line per row, RFC 4180).
  const fs::path csv = dir.write("trials.csv", table.csv());
  const record::ResultsTable back = record::ResultsFile(csv).read();
  EXPECT_EQ(back.columns, table.columns);
  EXPECT_EQ(back.rows, table.rows);

  // Trial 2 of the experiment's curves by trial: one participant per group.
  const std::vector<CurvePoint> curves = learningCurves(table.trials, {"time_s"});
  int checked = 0;
  for (const CurvePoint& p : curves)
    if (p.scope == "group" && p.by == "block" && p.blockName == "train") {
      // guided: p1's train mean (9 + 4) / 2; control: p2's (8 + 7) / 2.
      EXPECT_DOUBLE_EQ(p.mean, p.group == "guided" ? 6.5 : 7.5);
      ++checked;
    }
  EXPECT_EQ(checked, 2);
}

TEST(ExperimentTableTest, AFolderWithoutSessionsIsNamed) {
  test::TempDirectory dir;
  fs::create_directories(dir.path() / "empty");
  EXPECT_FALSE(isExperimentFolder(dir.path() / "empty"));
  try {
    (void)readExperiment(dir.path() / "empty");
    FAIL() << "no error";
  } catch (const AnalysisInputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("holds no session folders"));
  }
}

}  // namespace
}  // namespace hemiroll::game
