// The whole path a lab takes with a between-subjects study (issue 30's
// "done when"), end to end through the real binary: a three-group,
// counterbalanced protocol (levels/protocols/groups_demo.lua) run for a
// cohort of simulated participants (`session --participants 6 --bot
// human`), exported (`bids`, checked against the required files and
// columns), analysed as an experiment (`analyze EXPERIMENT_FOLDER`: the
// long table with its columns, the learning curves and their plots), and
// the protocol checked (`check`).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "engine/record/ResultsFile.h"
#include "tests/game/support/BidsChecks.h"
#include "tests/support/ProcessRunner.h"
#include "tests/support/TempDirectory.h"
#include "tests/support/XmlCheck.h"

namespace hemiroll::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const std::string kBinary = HEMIROLL_BINARY;
const std::string kSource = HEMIROLL_SOURCE_DIR;
const std::string kProtocol = kSource + "/levels/protocols/groups_demo.lua";

TEST(StudyPathTest, ACounterbalancedThreeGroupStudyGoesFromSessionsThroughBidsToLearningCurves) {
  TempDirectory dir;
  const fs::path data = dir.path() / "data";
  // 1. The cohort: six simulated participants, one after the other.
  const ProcessResult session = runProcess(kBinary, {"session", kProtocol, "--participants", "6", "--bot", "human",
                                                     "--human-device", "haptic", "--data", data.string()});
  ASSERT_EQ(session.exitCode, 0) << session.err;
  EXPECT_THAT(session.out, HasSubstr("{\"event\":\"cohort\",\"participants\":6,"));
  const fs::path experiment = data / "groups-demo";
  // Balanced by arrival: two per group, one of each block order per group.
  std::map<std::string, std::set<std::string>> ordersOf;  // group -> its participants' first post-training block
  for (int k = 1; k <= 6; ++k) {
    const fs::path folder = experiment / ("sim-0" + std::to_string(k)) / "1";
    const record::ResultsTable results = record::ResultsFile(folder / "results.csv").read();
    ASSERT_EQ(results.rows.size(), 5u) << folder;
    const auto at = [&](const char* name) {
      return static_cast<std::size_t>(std::find(results.columns.begin(), results.columns.end(), name) -
                                      results.columns.begin());
    };
    ordersOf[results.rows[0][at("group")]].insert(results.rows[3][at("block_name")]);
    EXPECT_TRUE(fs::exists(folder / "bot-memory.json"));
  }
  EXPECT_EQ(ordersOf, (std::map<std::string, std::set<std::string>>{{"guided", {"retention", "transfer"}},
                                                                     {"augmented", {"retention", "transfer"}},
                                                                     {"control", {"retention", "transfer"}}}));

  // 2. BIDS: the required files and columns; the groups in participants.tsv.
  const fs::path bids = dir.path() / "bids";
  const ProcessResult exported = runProcess(kBinary, {"bids", experiment.string(), "--out", bids.string()});
  ASSERT_EQ(exported.exitCode, 0) << exported.err;
  expectValidBidsMotion(bids, 30);
  const std::vector<std::string> participants = lines(slurp(bids / "participants.tsv"));
  ASSERT_EQ(participants.size(), 7u);
  EXPECT_EQ(participants[0], "participant_id\tgroup\tblock_order");
  EXPECT_EQ(participants[1], "sub-sim01\tguided\t1");
  EXPECT_EQ(participants[5], "sub-sim05\taugmented\t2");

  // 3. The experiment analysed: the long table, the curves, the plots.
  const fs::path analysis = dir.path() / "analysis";
  const ProcessResult analysed = runProcess(kBinary, {"analyze", experiment.string(), "--out", analysis.string()});
  ASSERT_EQ(analysed.exitCode, 0) << analysed.err;
  EXPECT_THAT(analysed.out, HasSubstr("| guided | 2 | 10 |"));
  const record::ResultsTable trials = record::ResultsFile(analysis / "trials.csv").read();
  EXPECT_EQ(trials.rows.size(), 30u);
  for (const char* column : {"participant", "group", "block_order", "block", "block_name", "condition",
                             "condition_label", "trial_in_block", "outcome", "time_s", "guidance", "guidance_fade",
                             "stages_passed", "stage_times_s", "contact_path_m", "point_path_m", "effort_N2_s",
                             "smoothness_m2_per_s6", "best_margin", "final_margin", "movement_duration_s",
                             "movement_steady_rate_rad_per_s", "movement_drift_speed_m_per_s"})
    EXPECT_NE(std::find(trials.columns.begin(), trials.columns.end(), column), trials.columns.end()) << column;
  const record::ResultsTable curves = record::ResultsFile(analysis / "learning_curves.csv").read();
  EXPECT_EQ(curves.columns,
            (std::vector<std::string>{"scope", "participant", "group", "by", "x", "block_name", "measure", "n", "mean", "sd"}));
  EXPECT_FALSE(curves.rows.empty());
  for (const char* plot : {"curves_success_by_trial.svg", "curves_time_s_by_block.svg",
                           "participants_final_margin_by_trial.svg"}) {
    ASSERT_TRUE(fs::exists(analysis / plot)) << plot;
    EXPECT_EQ(xmlProblem(slurp(analysis / plot)), "") << plot;
  }

  // 4. The protocol checks out.
  const ProcessResult checked = runProcess(kBinary, {"check", kProtocol});
  EXPECT_EQ(checked.exitCode, 0) << checked.out << checked.err;
}

}  // namespace
}  // namespace hemiroll::test
