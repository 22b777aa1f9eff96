// game/research/sweep/SbatchDirectives: the values sbatch takes and the hand-added
// #SBATCH lines carried into a job file written again. That sbatch itself
// reads the quoted paths so is tools/slurm-sweep-check.sh (ctest -L heavy).

#include "game/research/sweep/SbatchDirectives.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(SbatchDirectivesTest, TimeLimitsInEverySlurmFormAndNothingElse) {
  for (const char* good : {"90", "30:00", "2:30:00", "1-12", "1-12:30", "1-12:30:00", "UNLIMITED"})
    EXPECT_FALSE(slurmTimeProblem(good)) << good;
  for (const char* bad : {"", "1h", "1:2:3:4", "a-1", "1-", "-5", "1.5", "90 ", "1-2:3:4:5", "61:99", "1:60:00",
                          "2-24", "99999999999"})
    EXPECT_TRUE(slurmTimeProblem(bad)) << bad;
  // Zero would ask for no limit at all.
  ASSERT_TRUE(slurmTimeProblem("0:00"));
  EXPECT_THAT(*slurmTimeProblem("0-0"), HasSubstr("no limit"));
}

TEST(SbatchDirectivesTest, NamesAndMemory) {
  EXPECT_FALSE(slurmNameProblem("gpu_a100.x-1"));
  EXPECT_FALSE(slurmNameProblem("short,long"));
  for (const char* bad : {"", "a b", "a;rm", "a\nb", "$HOME", ",", "a,,b", "a,"}) EXPECT_TRUE(slurmNameProblem(bad)) << bad;
  for (const char* good : {"4G", "500M", "0", "1024", "2t"}) EXPECT_FALSE(slurmMemoryProblem(good)) << good;
  for (const char* bad : {"", "G", "4GB", "1.5G", "-1", "4 G", "99999999999999999999999G"})
    EXPECT_TRUE(slurmMemoryProblem(bad)) << bad;
}

TEST(SbatchDirectivesTest, PathValuesAreOneQuotedWordWithLiteralPercents) {
  EXPECT_EQ(sbatchPathValue("/a b/100%", "task-%a.log"), "\"/a b/100%%/task-%a.log\"");
  EXPECT_EQ(sbatchPathValue("/say \"hi\"", "m.log"), "\"/say \\\"hi\\\"/m.log\"");
}

TEST(SbatchDirectivesTest, OptionsAreNamedByTheirLongForm) {
  EXPECT_EQ(sbatchOption("#SBATCH --time=10"), "time");
  EXPECT_EQ(sbatchOption("  #SBATCH -t 10"), "time");
  EXPECT_EQ(sbatchOption("#SBATCH --qos high"), "qos");
  EXPECT_EQ(sbatchOption("#SBATCH -A lab"), "account");
  EXPECT_EQ(sbatchOption("#SBATCH\t--mem=1G"), "mem");
  EXPECT_EQ(sbatchOption("#SBATCHX --time=1"), "");
  EXPECT_EQ(sbatchOption("# SBATCH --time=1"), "");
  EXPECT_EQ(sbatchOption("echo #SBATCH --time=1"), "");
}

TEST(SbatchDirectivesTest, HandAddedLinesAreCarriedBeforeTheFirstCommand) {
  const std::string fresh = "#!/bin/bash\n#SBATCH --job-name=j\n#SBATCH --time=60\nset -e\nexec x\n";
  const std::string previous =
      "#!/bin/bash\n#SBATCH --job-name=j\n#SBATCH --qos=high\n#SBATCH -t 30\n# a note of the user's\n"
      "module load gcc\nset -e\n#SBATCH --mail-user=late\nexec x\n";
  const CarriedDirectives c = carryHandAddedDirectives(previous, fresh);
  EXPECT_EQ(c.text,
            "#!/bin/bash\n#SBATCH --job-name=j\n#SBATCH --time=60\n"
            "# Kept from the previous file (hemiroll does not write these):\n#SBATCH --qos=high\nset -e\nexec x\n");
  EXPECT_EQ(c.kept, std::vector<std::string>{"#SBATCH --qos=high"});
  EXPECT_EQ(c.replaced, std::vector<std::string>{"#SBATCH -t 30"});
  // A command is not carried (it could depend on lines around it), only
  // reported; a #SBATCH line after the first command was never read by
  // sbatch, so it is not made to count now.
  EXPECT_EQ(c.dropped, std::vector<std::string>{"module load gcc"});
}

TEST(SbatchDirectivesTest, HemirollsOwnOptionsAreNamedAndRetiredNotKept) {
  const std::string fresh = "#!/bin/bash\n#SBATCH --job-name=j\nset -e\n";
  EXPECT_EQ(writtenOptionsLine("#!/bin/bash\n#SBATCH --job-name=j\n#SBATCH -t 5\nset -e\n#SBATCH --qos=x\n"),
            "# hemiroll wrote the #SBATCH options: job-name time");
  const std::string previous =
      "#!/bin/bash\n#SBATCH --job-name=j\n#SBATCH --time=90\n#SBATCH --qos=high\n"
      "# hemiroll wrote the #SBATCH options: job-name time\nset -e\n";
  const CarriedDirectives c = carryHandAddedDirectives(previous, fresh);
  EXPECT_EQ(c.retired, std::vector<std::string>{"#SBATCH --time=90"});
  EXPECT_EQ(c.kept, std::vector<std::string>{"#SBATCH --qos=high"});
  EXPECT_THAT(c.text, Not(HasSubstr("--time")));
}

TEST(SbatchDirectivesTest, TheSameFileAgainChangesNothing) {
  const std::string fresh = "#!/bin/bash\n#SBATCH --job-name=j\nset -e\n";
  const CarriedDirectives c = carryHandAddedDirectives(fresh, fresh);
  EXPECT_EQ(c.text, fresh);
  EXPECT_TRUE(c.kept.empty() && c.replaced.empty() && c.dropped.empty());
  // ... and a file carried once carries the same lines again, once.
  const std::string withOwn = carryHandAddedDirectives("#SBATCH --qos=a\n", fresh).text;
  const CarriedDirectives twice = carryHandAddedDirectives(withOwn, fresh);
  EXPECT_EQ(twice.text, withOwn);
  EXPECT_TRUE(twice.dropped.empty());
}

}  // namespace
}  // namespace hemiroll::game
