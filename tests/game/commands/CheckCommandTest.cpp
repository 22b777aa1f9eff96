// `hemiroll check`, end to end (the real binary) and its kind guess: every
// shipped file is clean; a broken level names its file and line; a level
// that loads but cannot be played is told why (the device, a hold, a
// target out of reach, a failing score); a protocol is checked through its
// conditions' levels; a missing file or a FIFO is a problem, not a hang.
#include "game/commands/CheckCommand.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <sys/stat.h>
#include <vector>

#include "tests/support/ProcessRunner.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

const std::string kBinary = HEMIROLL_BINARY;
const std::string kSource = HEMIROLL_SOURCE_DIR;

ProcessResult check(const std::vector<std::string>& args) {
  std::vector<std::string> all = {"check"};
  all.insert(all.end(), args.begin(), args.end());
  return runProcess(kBinary, all);
}

constexpr const char* kUnplayable = R"lua(
return { name = "unplayable", force = { method = "M3", kr = 5000, kv = 10, alpha = 2 },
  task = { time_limit = 10, stages = {
    { name = "reach", hold = 12, targets = { u_ca = { value = { 0.5, 0 }, tol = 0.004 } } } } },
  score = function(s) return s.nonexistent.field end,
  medals = { bronze = 1, silver = 2, gold = 3 } }
)lua";

TEST(CheckCommandTest, EveryShippedFileIsClean) {
  std::vector<std::string> files;
  for (const char* folder : {"/levels", "/levels/protocols", "/levels/scenarios", "/levels/sweeps", "/levels/generated"})
    for (const auto& entry : std::filesystem::directory_iterator(kSource + folder))
      if (entry.path().extension() == ".lua") files.push_back(entry.path().string());
  ASSERT_GT(files.size(), 20u);
  const ProcessResult r = check(files);
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_THAT(r.out, Not(HasSubstr("problem")));
  EXPECT_THAT(r.out, HasSubstr("paper_guidance.lua: ok (protocol)"));
  EXPECT_THAT(r.out, HasSubstr("rose_paper.lua: ok (scenario)"));
  EXPECT_THAT(r.out, HasSubstr("rose_k_omega.lua: ok (sweep spec)"));
  EXPECT_THAT(r.out, HasSubstr("paper_reaching.lua: ok (level)"));
}

TEST(CheckCommandTest, ALevelThatLoadsButCannotBePlayedIsToldWhyEveryTime) {
  TempDirectory dir;
  const std::string level = dir.write("unplayable.lua", kUnplayable);
  const ProcessResult r = check({level});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.out, HasSubstr("4 problems (as a level)"));
  EXPECT_THAT(r.out, HasSubstr("the 'bot' device renders stably"));
  EXPECT_THAT(r.out, HasSubstr("stage 1 (\"reach\") asks for a hold of 12 s, not shorter than the time limit of 10 s"));
  EXPECT_THAT(r.out, HasSubstr("beyond its reach"));
  EXPECT_THAT(r.out, HasSubstr("the score function fails on a won trial"));
  EXPECT_THAT(r.out, HasSubstr("unplayable.lua:5:"));  // the score's own line

  // Through a protocol: the condition's level and where it sits.
  const std::string protocol =
      dir.write("study.lua", "return { experiment = \"x\", blocks = { { name = \"train\", conditions = { { level = "
                             "\"unplayable.lua\" } } } } }\n");
  const ProcessResult p = check({protocol});
  EXPECT_EQ(p.exitCode, 2);
  EXPECT_THAT(p.out, HasSubstr("(as a protocol)"));
  EXPECT_THAT(p.out, HasSubstr("block 1 (\"train\"), condition 1"));
  EXPECT_THAT(p.out, HasSubstr("beyond its reach"));
}

// A group plays its blocks under its changes: each group's conditions are
// checked as that group plays them, and the participants file line by line.
TEST(CheckCommandTest, EachGroupsConditionsAndTheParticipantsFileAreChecked) {
  TempDirectory dir;
  dir.write("participants.tsv", "participant_id\tgroup\np01\tstiff\np02\tsoft\n");
  const std::string protocol = dir.write(
      "groups.lua",
      "return { experiment = \"g\", assignment = \"participants_file\", participants = \"participants.tsv\",\n"
      "  groups = { { name = \"stiff\", changes = { { block = \"train\", kr = 5000 } } }, { name = \"plain\" } },\n"
      "  blocks = { { name = \"train\", level = \"" + kSource + "/levels/tutorial_01_tilt_and_return.lua\" } } }\n");
  const ProcessResult r = check({protocol});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.out, HasSubstr("group \"stiff\", block 1 (\"train\"), condition 1 (\"kr 5000\""));
  EXPECT_THAT(r.out, HasSubstr("the 'bot' device renders stably"));
  EXPECT_THAT(r.out, Not(HasSubstr("group \"plain\"")));  // a group that changes nothing plays the blocks as checked
  EXPECT_THAT(r.out, HasSubstr("participants.tsv:3: column 'group': no group 'soft' in the protocol"));
}

// A protocol that names its device: each condition's coupling is checked
// against the profile, and a profile that cannot be loaded is named.
TEST(CheckCommandTest, AProtocolsDeviceProfileHoldsEveryCondition) {
  TempDirectory dir;
  dir.write("soft.lua", "return { model = 'Soft Device', peak_force_N = 3, continuous_force_N = 1,"
                        " max_stiffness_N_per_m = 400, workspace_width_m = 0.2, workspace_depth_m = 0.2,"
                        " workspace_height_m = 0.2, update_rate_Hz = 1000 }");
  const std::string level = kSource + "/levels/tutorial_02_roll_a_short_distance.lua";  // M3, kr 250, alpha 2
  const std::string protocol = dir.write(
      "study.lua", "return { experiment = 'x', device_profile = 'soft.lua', blocks = { { level = '" + level + "' } } }");
  const ProcessResult r = check({protocol});
  EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("asks for a coupling stiffness of 500 N/m (k_r 250 N/m times alpha 2), above the Soft "
                               "Device's maximum stiffness of 400 N/m"));
  const std::string unknown = dir.write(
      "unknown.lua", "return { experiment = 'x', device_profile = 'phantom9000', blocks = { { level = '" + level + "' } } }");
  const ProcessResult u = check({unknown});
  EXPECT_EQ(u.exitCode, 2);
  EXPECT_THAT(u.out, HasSubstr("device_profile: unknown device profile 'phantom9000'"));
}

// With a device profile, conditions are held to that device only: an omega.3
// renders 1200 N/m, which the bot's desk device (1000 N/m) would refuse.
TEST(CheckCommandTest, AProtocolWithAStiffDeviceIsNotHeldToTheBotsDevice) {
  TempDirectory dir;
  const std::string protocol = dir.write(
      "stiff.lua", "return { experiment = 'x', device_profile = 'omega3', blocks = { { level = '" + kSource +
                       "/levels/tutorial_02_roll_a_short_distance.lua', kr = 600,\n"
                       "  guidance = { kind = 'autopilot', stiffness = 1100 } } } }");
  const ProcessResult r = check({protocol});
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_THAT(r.out, Not(HasSubstr("renders stably")));
}

// A protocol kept outside a levels folder is checked as session runs it.
TEST(CheckCommandTest, LevelsAreLookedForWhereSessionLooks) {
  TempDirectory dir;
  const std::string protocol =
      dir.write("p.lua", "return { experiment = 'x', blocks = { { level = 'tutorial_01_tilt_and_return.lua' } } }");
  EXPECT_EQ(check({protocol}).exitCode, 2);
  const ProcessResult r = check({protocol, "--levels", kSource + "/levels"});
  EXPECT_EQ(r.exitCode, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("ok (protocol)"));
}

TEST(CheckCommandTest, ALoadErrorNamesTheFileAndLineAndTheRestAreStillChecked) {
  TempDirectory dir;
  const std::string broken =
      dir.write("broken.lua", "return { name = \"b\",\n task = { targets = { u_ca = { value = { 0.01, 0 }, tol = -1 } } } }\n");
  const std::string fifo = (dir.path() / "fifo.lua").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const ProcessResult r = check({broken, dir.path().string() + "/missing.lua", fifo, kSource + "/levels/paper_reaching.lua"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.out, HasSubstr("broken.lua:2: task.targets.u_ca.tol"));
  EXPECT_THAT(r.out, HasSubstr("missing.lua: no such file"));
  EXPECT_THAT(r.out, HasSubstr("not a regular file"));
  EXPECT_THAT(r.out, HasSubstr("paper_reaching.lua: ok (level)"));
}

TEST(CheckCommandTest, AWrongFlagIsUsage) {
  const ProcessResult r = check({"--as", "nothing", "x.lua"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("'level', 'protocol', 'scenario' or 'sweep'"));
  EXPECT_EQ(check({}).exitCode, 2);
}

TEST(CheckCommandTest, TheKindIsGuessedFromTheKeys) {
  using game::CheckedKind;
  EXPECT_EQ(game::guessKind("return { experiment = 'x', blocks = {} }"), CheckedKind::Protocol);
  EXPECT_EQ(game::guessKind("return {\n drive = { r1 = 0.01 },\n duration = 35,\n axes = {} }"), CheckedKind::Sweep);
  EXPECT_EQ(game::guessKind("return { drive = { kind = 'rose' }, duration = 35 }"), CheckedKind::Scenario);
  EXPECT_EQ(game::guessKind("return { name = 'l', task = { targets = {} } }"), CheckedKind::Level);
  // A word inside another name is not the key.
  EXPECT_EQ(game::guessKind("return { name = 'l', task = {}, myblocks = 1 }"), CheckedKind::Level);
}

}  // namespace
}  // namespace hemiroll::test
