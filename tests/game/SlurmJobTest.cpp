// game/sweep/SlurmJob: the job files `hemiroll sweep --slurm N` writes. That
// they run on a real cluster and merge to the one-machine bytes is
// tools/slurm-sweep-check.sh (ctest -L heavy: tools.SlurmSweepMatchesOneMachine).

#include "game/sweep/SlurmJob.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "game/sweep/SweepError.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

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
  EXPECT_THAT(f.array, HasSubstr("#SBATCH --output=/scratch/ana/k/slurm/task-%a.log\n"));
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
  EXPECT_THAT(slurmJobFiles(d).array, HasSubstr("#SBATCH --output=/scratch/100%%/k/slurm/task-%a.log\n"));
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
}

TEST(SlurmJobTest, TheFilesAreWrittenExecutable) {
  test::TempDirectory dir;
  SlurmJobDef d = job();
  d.out = dir.path() / "sweep";
  const auto files = writeSlurmJob(d);
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
