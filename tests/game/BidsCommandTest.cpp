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

#include "tests/support/ProcessRunner.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const std::string kBinary = HEMIROLL_BINARY;
const std::string kSource = HEMIROLL_SOURCE_DIR;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  for (std::string line; std::getline(s, line);) out.push_back(line);
  return out;
}

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string c; std::getline(s, c, '\t');) out.push_back(c);
  return out;
}

// The session the tutorial protocol makes with its solver: three trials.
fs::path runSession(const TempDirectory& dir) {
  const ProcessResult r =
      runProcess(kBinary, {"session", kSource + "/levels/protocols/tutorial_demo.lua", "--participant", "p01", "--data",
                           (dir.path() / "data").string(), "--bot", kSource + "/scripts/bots/tutorial_solver.lua"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return dir.path() / "data" / "tutorial-demo";
}

// The checks a BIDS validator makes that need no schema files.
void expectValidBidsMotion(const fs::path& root, int trials) {
  const nlohmann::json description = nlohmann::json::parse(slurp(root / "dataset_description.json"));
  EXPECT_TRUE(description.contains("Name"));
  EXPECT_TRUE(description.contains("BIDSVersion"));
  const std::vector<std::string> participants = lines(slurp(root / "participants.tsv"));
  ASSERT_GE(participants.size(), 2u);
  EXPECT_EQ(cells(participants[0]).front(), "participant_id");
  std::set<std::string> subjects;
  for (std::size_t i = 1; i < participants.size(); ++i) subjects.insert(cells(participants[i]).front());
  EXPECT_TRUE(fs::exists(root / "README"));

  const std::regex motionName(
      R"(sub-([A-Za-z0-9]+)(_ses-[A-Za-z0-9]+)?_task-[A-Za-z0-9]+_tracksys-[A-Za-z0-9]+(_run-[0-9]+)?_motion\.tsv)");
  const std::regex eventsName(R"(sub-[A-Za-z0-9]+(_ses-[A-Za-z0-9]+)?_task-[A-Za-z0-9]+(_run-[0-9]+)?_events\.tsv)");
  int motions = 0, events = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    std::smatch m;
    if (std::regex_match(name, m, motionName)) {
      ++motions;
      EXPECT_EQ(entry.path().parent_path().filename(), "motion") << name;
      EXPECT_TRUE(subjects.count("sub-" + m[1].str())) << name << " has no row in participants.tsv";
      const std::string stem = name.substr(0, name.size() - std::string("_motion.tsv").size());
      const fs::path channelsFile = entry.path().parent_path() / (stem + "_channels.tsv");
      const fs::path sidecar = entry.path().parent_path() / (stem + "_motion.json");
      ASSERT_TRUE(fs::exists(channelsFile)) << stem;
      ASSERT_TRUE(fs::exists(sidecar)) << stem;
      const std::vector<std::string> channels = lines(slurp(channelsFile));
      ASSERT_FALSE(channels.empty());
      const std::vector<std::string> header = cells(channels[0]);
      EXPECT_EQ(std::vector<std::string>(header.begin(), header.begin() + 5),
                (std::vector<std::string>{"name", "component", "type", "tracked_point", "units"}));
      const std::vector<std::string> rows = lines(slurp(entry.path()));
      ASSERT_FALSE(rows.empty()) << name;
      EXPECT_EQ(cells(rows.front()).size(), channels.size() - 1) << name << ": one channel per column";
      const nlohmann::json json = nlohmann::json::parse(slurp(sidecar));
      for (const char* key : {"TaskName", "SamplingFrequency", "TrackingSystemName"})
        EXPECT_TRUE(json.contains(key)) << stem << " lacks " << key;
    } else if (std::regex_match(name, eventsName)) {
      ++events;
      const std::vector<std::string> rows = lines(slurp(entry.path()));
      ASSERT_GE(rows.size(), 2u);
      const std::vector<std::string> header = cells(rows[0]);
      ASSERT_GE(header.size(), 2u);
      EXPECT_EQ(header[0], "onset");
      EXPECT_EQ(header[1], "duration");
      for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_EQ(cells(rows[i]).size(), header.size()) << name;
    } else if (entry.is_regular_file() && entry.path().parent_path() != root) {
      EXPECT_TRUE(name.find("_channels.tsv") != std::string::npos || name.find("_motion.json") != std::string::npos)
          << "a file BIDS does not name: " << name;
    }
  }
  EXPECT_EQ(motions, trials);
  EXPECT_EQ(events, trials);
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
