// `hemiroll bids`, end to end: a session run by a bot, exported, and the
// dataset checked against the BIDS rules that can be checked here (the
// required files and their required columns and keys, the file names'
// entities, one channel per motion column), with an unfinished trial left
// out and named, never exported as if whole.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/game/support/BidsChecks.h"
#include "tests/support/ProcessRunner.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const std::string kBinary = HEMIROLL_BINARY;
const std::string kSource = HEMIROLL_SOURCE_DIR;

// The session the tutorial protocol makes with its solver: three trials.
fs::path runSession(const TempDirectory& dir) {
  const ProcessResult r =
      runProcess(kBinary, {"session", kSource + "/levels/protocols/tutorial_demo.lua", "--participant", "p01", "--data",
                           (dir.path() / "data").string(), "--bot", kSource + "/scripts/bots/tutorial_solver.lua"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return dir.path() / "data" / "tutorial-demo";
}

TEST(BidsCommandTest, ASessionBecomesAValidDatasetWithItsProtocolInTheEvents) {
  TempDirectory dir;
  const fs::path experiment = runSession(dir);
  const fs::path out = dir.path() / "bids";
  const ProcessResult r = runProcess(kBinary, {"bids", experiment.string(), "--out", out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("3 trials of 1 participant in"));
  expectValidBidsMotion(out, 3);
  const std::string events = slurp(out / "sub-p01" / "ses-1" / "motion" / "sub-p01_ses-1_task-tutorialdemo_run-2_events.tsv");
  EXPECT_THAT(events, HasSubstr("block_name"));
  EXPECT_THAT(events, HasSubstr("\troll\t"));  // the block's name, from the protocol
  EXPECT_THAT(events, HasSubstr("\talpha 1.5\t"));  // the condition's label
  EXPECT_THAT(events, HasSubstr("\tsuccess\ttarget held"));
  // Each stage passed, at the time results.csv gives it (stage_times_s).
  EXPECT_THAT(events, HasSubstr("\tstage_passed\t"));
  EXPECT_EQ(lines(slurp(out / "participants.tsv"))[0], "participant_id\tgroup\tblock_order");
  EXPECT_EQ(lines(slurp(out / "participants.tsv"))[1], "sub-p01\tn/a\t1");
  const nlohmann::json description = nlohmann::json::parse(slurp(out / "dataset_description.json"));
  EXPECT_EQ(description["Name"], "tutorial-demo");
}

TEST(BidsCommandTest, AnUnfinishedTrialIsLeftOutAndNamed) {
  TempDirectory dir;
  const fs::path experiment = runSession(dir);
  const fs::path session = experiment / "p01" / "1";
  // Trial 2 as a killed session leaves it: a sidecar without an outcome.
  nlohmann::json sidecar = nlohmann::json::parse(slurp(session / "trial-002.json"));
  sidecar["complete"] = false;
  sidecar["outcome"] = nullptr;
  std::ofstream(session / "trial-002.json") << sidecar.dump(2);
  const fs::path out = dir.path() / "bids";
  const ProcessResult r = runProcess(kBinary, {"bids", session.string(), "--out", out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("left out"));
  EXPECT_THAT(r.err, HasSubstr("trial-002.csv"));
  EXPECT_THAT(r.out, HasSubstr("2 trials of 1 participant in"));
  expectValidBidsMotion(out, 2);
  EXPECT_FALSE(fs::exists(out / "sub-p01" / "ses-1" / "motion" / "sub-p01_ses-1_task-tutorialdemo_run-2_events.tsv"));
}

// Ids that differ only in what BIDS labels drop ("p-1" and "p1") would
// write the same files: refused before anything is written, as is an --out
// that already holds something (an earlier export's subjects would look
// like this one's). A finished trial whose samples are missing is named.
TEST(BidsCommandTest, TrialsThatWouldShareNamesAreRefusedAndNothingIsLost) {
  TempDirectory dir;
  const fs::path data = dir.path() / "data";
  for (const char* who : {"p-1", "p1"}) {
    const ProcessResult r = runProcess(kBinary, {"session", kSource + "/levels/protocols/tutorial_demo.lua", "--participant",
                                                 who, "--data", data.string(), "--bot",
                                                 kSource + "/scripts/bots/tutorial_solver.lua"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  const fs::path out = dir.path() / "bids";
  ProcessResult r = runProcess(kBinary, {"bids", (data / "tutorial-demo").string(), "--out", out.string()});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("would both be sub-p1_ses-1"));
  EXPECT_FALSE(fs::exists(out));
  // One of them alone is fine; a second export into the same folder is not.
  r = runProcess(kBinary, {"bids", (data / "tutorial-demo" / "p1").string(), "--out", out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = runProcess(kBinary, {"bids", (data / "tutorial-demo" / "p-1").string(), "--out", out.string()});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("exists and is not empty"));
  // A finished trial without its samples.
  fs::remove(data / "tutorial-demo" / "p-1" / "1" / "trial-003.csv");
  r = runProcess(kBinary, {"bids", (data / "tutorial-demo" / "p-1").string(), "--out", (dir.path() / "b2").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("trial-003.json: its samples (trial-003.csv) are missing"));
  EXPECT_THAT(r.out, HasSubstr("2 trials of 1 participant in"));
}

TEST(BidsCommandTest, BadInputIsNamed) {
  TempDirectory dir;
  ProcessResult r = runProcess(kBinary, {"bids", dir.path().string(), "--out", (dir.path() / "b").string()});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("no session folder in it"));
  r = runProcess(kBinary, {"bids", dir.path().string()});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("missing --out DIR"));
  r = runProcess(kBinary, {"bids", (dir.path() / "nope").string(), "--out", (dir.path() / "b").string()});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("not a folder"));
}

}  // namespace
}  // namespace hemiroll::test
