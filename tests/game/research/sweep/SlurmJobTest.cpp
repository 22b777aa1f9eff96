// game/research/sweep/SlurmJob: the job files `hemiroll sweep --slurm N` writes. That
// they run on a real cluster and merge to the one-machine bytes is
// tools/slurm-sweep-check.sh (ctest -L heavy: tools.SlurmSweepMatchesOneMachine).

#include "game/research/sweep/SlurmJob.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "game/research/sweep/SweepError.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

SlurmJobDef job() {
  SlurmJobDef d;
  d.program = "/opt/hemiroll/bin/hemiroll";
  d.spec = "/home/ana/sweeps/it's k.lua";  // a quote and a space: one word each still
  d.out = "/scratch/ana/k";
  d.tasks = 32;
  d.threadsPerTask = 8;
  return d;
}

TEST(SlurmJobTest, OneArrayTaskPerShardIntoThePartsFolder) {
  const SlurmJobFiles f = slurmJobFiles(job());
  EXPECT_THAT(f.array, HasSubstr("#SBATCH --array=0-31\n"));
  EXPECT_THAT(f.array, HasSubstr("#SBATCH --cpus-per-task=8\n"));
  EXPECT_THAT(f.array, HasSubstr("#SBATCH --output=\"/scratch/ana/k/slurm/task-%a.log\"\n"));
  EXPECT_THAT(f.array, HasSubstr("exec '/opt/hemiroll/bin/hemiroll' sweep '/home/ana/sweeps/it'\\''s k.lua' "
                                 "--out '/scratch/ana/k/parts' --shard \"${SLURM_ARRAY_TASK_ID}/32\""));
  EXPECT_THAT(f.merge, HasSubstr("sweep merge '/scratch/ana/k/parts' --out '/scratch/ana/k' --maps svg\n"));
  EXPECT_THAT(f.submit, HasSubstr("--dependency=afterok:\"$array\""));
  EXPECT_THAT(f.submit, HasSubstr("--kill-on-invalid-dep=yes"));
}

TEST(SlurmJobTest, ShellQuotingKeepsEveryPathOneWord) {
  EXPECT_EQ(shellQuote("a b"), "'a b'");
  EXPECT_EQ(shellQuote("it's"), "'it'\\''s'");
  EXPECT_EQ(shellQuote("$HOME `x`"), "'$HOME `x`'");
  // Through bash itself: the words come back as they went in.
  test::TempDirectory dir;
  const std::string word = "it's a $HOME `x` \"y\"";
  const std::string script = (dir.path() / "echo.sh").string();
  std::ofstream(script) << "printf '%s' " << shellQuote(word) << " > " << shellQuote((dir.path() / "out").string())
                        << "\n";
  ASSERT_EQ(std::system(("bash " + script).c_str()), 0);
  std::stringstream back;
  back << std::ifstream(dir.path() / "out").rdbuf();
  EXPECT_EQ(back.str(), word);
}

TEST(SlurmJobTest, PathsThatWouldBreakAnSbatchLineAreHandled) {
  SlurmJobDef d = job();
  d.out = "/scratch/100%/k";  // % is a field in Slurm's file name patterns
  EXPECT_THAT(slurmJobFiles(d).array, HasSubstr("#SBATCH --output=\"/scratch/100%%/k/slurm/task-%a.log\"\n"));
  // sbatch splits an #SBATCH line on spaces outside double quotes, and reads
  // \" inside them as a quote (tools/slurm-sweep-check.sh runs such a path).
  d.out = "/scratch/my \"k\" sweep";
  EXPECT_THAT(slurmJobFiles(d).merge, HasSubstr("#SBATCH --output=\"/scratch/my \\\"k\\\" sweep/slurm/merge.log\"\n"));
  test::TempDirectory dir;
  d.out = dir.path() / "a\nb";  // a line break would end the #SBATCH line
  try {
    writeSlurmJob(d);
    FAIL() << "no exception";
  } catch (const SweepError& e) {
    EXPECT_EQ(e.kind(), SweepError::Kind::BadInput);
    EXPECT_THAT(e.what(), HasSubstr("line break"));
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "a\nb"));
  d.out = dir.path() / "a\\b";  // sbatch would then name every task's log alike
  try {
    writeSlurmJob(d);
    FAIL() << "no exception";
  } catch (const SweepError& e) {
    EXPECT_EQ(e.kind(), SweepError::Kind::BadInput);
    EXPECT_THAT(e.what(), HasSubstr("backslash"));
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "a\\b"));
}

TEST(SlurmJobTest, ResourcesAreAskedByBothJobsAndAMissingTimeLimitIsSaid) {
  SlurmJobDef d = job();
  SlurmJobFiles f = slurmJobFiles(d);
  EXPECT_THAT(f.array, HasSubstr("# No --time"));
  EXPECT_THAT(f.array, Not(HasSubstr("#SBATCH --time")));
  d.resources = {"1-12:00:00", "short,long", "lab42", "4G"};
  f = slurmJobFiles(d);
  for (const std::string* text : {&f.array, &f.merge}) {
    EXPECT_THAT(*text, HasSubstr("#SBATCH --time=1-12:00:00\n"));
    EXPECT_THAT(*text, HasSubstr("#SBATCH --partition=short,long\n"));
    EXPECT_THAT(*text, HasSubstr("#SBATCH --account=lab42\n"));
    EXPECT_THAT(*text, HasSubstr("#SBATCH --mem=4G\n"));
    EXPECT_THAT(*text, Not(HasSubstr("# No --time")));
    // Every #SBATCH line before the first command: sbatch reads no further.
    EXPECT_LT(text->rfind("#SBATCH"), text->find("set -euo pipefail"));
  }
}

std::string readAll(const std::filesystem::path& p) {
  std::stringstream text;
  text << std::ifstream(p).rdbuf();
  return text.str();
}

TEST(SlurmJobTest, WritingAgainKeepsHandAddedLinesAndLosesNothing) {
  test::TempDirectory dir;
  SlurmJobDef d = job();
  d.out = dir.path() / "sweep";
  const auto first = writeSlurmJob(d);
  EXPECT_TRUE(first.notes.empty());
  const std::filesystem::path array = first.files[0], submit = first.files[2];
  std::string edited = readAll(array);
  edited.insert(edited.find("set -euo"), "#SBATCH --qos=high\n#SBATCH -t 30\n");
  std::ofstream(array) << edited;
  std::ofstream(submit, std::ios::app) << "module load hemiroll\n";

  d.resources.memory = "2G";
  const auto again = writeSlurmJob(d);
  const std::string rewritten = readAll(array);
  EXPECT_THAT(rewritten, HasSubstr("#SBATCH --qos=high\n"));
  EXPECT_THAT(rewritten, HasSubstr("#SBATCH -t 30\n"));
  EXPECT_THAT(rewritten, HasSubstr("#SBATCH --mem=2G\n"));
  EXPECT_LT(rewritten.rfind("#SBATCH"), rewritten.find("set -euo pipefail"));
  ASSERT_EQ(again.notes.size(), 2u);
  EXPECT_THAT(again.notes[0], HasSubstr("sweep-array.sbatch: kept"));
  EXPECT_THAT(again.notes[0], HasSubstr("--qos=high"));
  // submit.sh's hand-written command is not carried; the old file is kept.
  EXPECT_THAT(again.notes[1], HasSubstr("submit.sh.previous"));
  EXPECT_THAT(again.notes[1], HasSubstr("module load hemiroll"));
  EXPECT_THAT(readAll(submit.string() + ".previous"), HasSubstr("module load hemiroll"));
  EXPECT_THAT(readAll(submit), Not(HasSubstr("module load")));

  // A value given on the command line wins over the hand-written one, and says so.
  d.resources.time = "45";
  const auto third = writeSlurmJob(d);
  EXPECT_THAT(readAll(array), Not(HasSubstr("#SBATCH -t 30")));
  ASSERT_FALSE(third.notes.empty());
  EXPECT_THAT(third.notes[0], HasSubstr("#SBATCH --qos=high"));
  bool saidReplaced = false;
  for (const auto& note : third.notes) saidReplaced |= note.find("replaced by this command's values: #SBATCH -t 30") != std::string::npos;
  EXPECT_TRUE(saidReplaced);
}

// hemiroll's own lines of a previous run are its own, not the user's: a
// value no longer asked goes, and says so; the warning matches the file.
TEST(SlurmJobTest, AnOptionNoLongerAskedIsRetiredNotCarried) {
  test::TempDirectory dir;
  SlurmJobDef d = job();
  d.out = dir.path() / "sweep";
  d.resources.time = "1-00:00:00";
  d.resources.partition = "short";
  const auto first = writeSlurmJob(d);
  std::string edited = readAll(first.files[0]);
  edited.insert(edited.find("set -euo"), "#SBATCH --qos=high\n");
  std::ofstream(first.files[0]) << edited;
  d.resources = {};
  const auto again = writeSlurmJob(d);
  const std::string array = readAll(again.files[0]);
  EXPECT_THAT(array, Not(HasSubstr("--time=")));
  EXPECT_THAT(array, Not(HasSubstr("--partition=")));
  EXPECT_THAT(array, HasSubstr("# No --time"));
  EXPECT_THAT(array, HasSubstr("#SBATCH --qos=high\n"));  // the user's line stays
  bool retired = false;
  for (const auto& note : again.notes)
    retired |= note.find("sweep-array.sbatch: not written again") != std::string::npos &&
               note.find("#SBATCH --time=1-00:00:00") != std::string::npos;
  EXPECT_TRUE(retired);
  for (const auto& note : again.notes) EXPECT_THAT(note, Not(HasSubstr("kept the #SBATCH lines added to it: #SBATCH --time")));
}

TEST(SlurmJobTest, TheFilesAreWrittenExecutable) {
  test::TempDirectory dir;
  SlurmJobDef d = job();
  d.out = dir.path() / "sweep";
  const auto files = writeSlurmJob(d).files;
  ASSERT_EQ(files.size(), 3u);
  for (const auto& f : files) {
    EXPECT_TRUE(std::filesystem::exists(f)) << f;
    EXPECT_NE(std::filesystem::status(f).permissions() & std::filesystem::perms::owner_exec,
              std::filesystem::perms::none)
        << f;
  }
  EXPECT_EQ(files.back().filename(), "submit.sh");
}

}  // namespace
}  // namespace hemiroll::game
