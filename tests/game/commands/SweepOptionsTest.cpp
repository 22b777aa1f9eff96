// game/commands/SweepOptions: the three forms of `hemiroll sweep` and one
// sentence per wrong flag.

#include "game/commands/SweepOptions.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace hemiroll::game {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(SweepOptions, Run) {
  const SweepOptionsResult r = parseSweepOptions({"spec.lua", "--out", "d", "--threads", "3", "--shard=2/5", "--maps", "none"});
  ASSERT_EQ(r.error, "");
  const SweepOptions& o = r.options;
  EXPECT_EQ(o.action, SweepAction::Run);
  EXPECT_THAT(o.inputs, ElementsAre("spec.lua"));
  EXPECT_EQ(*o.out, "d");
  EXPECT_EQ(o.threads, 3);
  EXPECT_EQ(o.shard.index, 2);
  EXPECT_EQ(o.shard.count, 5);
  EXPECT_FALSE(o.maps);
  const SweepOptions plain = parseSweepOptions({"spec.lua", "--out", "d"}).options;
  EXPECT_EQ(plain.threads, 0);  // every core
  EXPECT_TRUE(plain.shard.whole());
  EXPECT_TRUE(plain.maps);
  EXPECT_EQ(plain.slurmTasks, 0);  // run here
  const SweepOptionsResult slurm = parseSweepOptions({"spec.lua", "--out", "d", "--slurm", "32", "--threads", "8"});
  ASSERT_EQ(slurm.error, "");
  EXPECT_EQ(slurm.options.slurmTasks, 32);
  const SweepOptionsResult asked = parseSweepOptions({"spec.lua", "--out", "d", "--slurm", "4", "--slurm-time", "1-00:00:00",
                                                      "--slurm-partition", "short", "--slurm-account", "lab",
                                                      "--slurm-mem", "4G"});
  ASSERT_EQ(asked.error, "");
  EXPECT_EQ(asked.options.slurm.time, "1-00:00:00");
  EXPECT_EQ(asked.options.slurm.partition, "short");
  EXPECT_EQ(asked.options.slurm.account, "lab");
  EXPECT_EQ(asked.options.slurm.memory, "4G");
  EXPECT_EQ(plain.lanes, 0);  // the widest this CPU runs
  EXPECT_EQ(parseSweepOptions({"spec.lua", "--out", "d", "--lanes", "4"}).options.lanes, 4);
}

TEST(SweepOptions, MergeAndMap) {
  const SweepOptionsResult merge = parseSweepOptions({"merge", "a", "b", "c", "--out", "m"});
  ASSERT_EQ(merge.error, "");
  EXPECT_EQ(merge.options.action, SweepAction::Merge);
  EXPECT_THAT(merge.options.inputs, ElementsAre("a", "b", "c"));
  const SweepOptionsResult map =
      parseSweepOptions({"map", "d", "--x", "k", "--y", "Omega", "--metric", "paper_like", "--aggregate", "best"});
  ASSERT_EQ(map.error, "");
  EXPECT_EQ(map.options.action, SweepAction::Map);
  EXPECT_EQ(*map.options.metric, "paper_like");
  EXPECT_EQ(*map.options.aggregate, Aggregate::Best);
  EXPECT_FALSE(map.options.out);
}

TEST(SweepOptions, EachMistakeIsOneSentence) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{}, "missing the sweep spec file"},
      {{"s.lua"}, "missing --out DIR"},
      {{"s.lua", "--out", "d", "--shard", "4/4"}, "--shard needs i/N with 0 <= i < N"},
      {{"s.lua", "--out", "d", "--threads", "0"}, "--threads needs a whole number of threads from 1 to 1024"},
      {{"s.lua", "--out", "d", "--maps", "png"}, "--maps needs 'svg' or 'none'"},
      {{"s.lua", "--out", "d", "--lanes", "3"}, "--lanes needs 1, 2, 4 or 8"},
      {{"merge", "a", "--out", "m", "--lanes", "2"}, "--lanes"},
      {{"s.lua", "t.lua", "--out", "d"}, "t.lua"},
      {{"merge", "--out", "m"}, "missing the part folders to merge"},
      {{"merge", "a", "--out", "m", "--shard", "0/2"}, "--shard"},
      {{"map", "d", "--x", "k", "--y", "Omega"}, "missing --x, --y or --metric"},
      {{"map", "d", "--x", "k", "--y", "Omega", "--metric", "curvature"}, "--metric needs one of paper_like"},
      {{"map", "d", "--x", "k", "--y", "Omega", "--metric", "loops", "--aggregate", "avg"}, "--aggregate needs median"},
      {{"map", "d", "--threads", "2"}, "--threads"},
      {{"s.lua", "--out", "d", "--slurm", "0"}, "--slurm needs a whole number of shards from 1 to 10000"},
      {{"s.lua", "--out", "d", "--slurm", "4", "--shard", "1/4"}, "--slurm writes a job for every shard"},
      {{"merge", "a", "--out", "m", "--slurm", "2"}, "--slurm"},
      {{"s.lua", "--out", "d", "--slurm", "2", "--slurm-time", "2h"}, "--slurm-time needs a time limit as Slurm writes it"},
      {{"s.lua", "--out", "d", "--slurm", "2", "--slurm-mem", "4GB"}, "--slurm-mem needs memory per node"},
      {{"s.lua", "--out", "d", "--slurm", "2", "--slurm-partition", "a b"}, "--slurm-partition needs a name"},
      {{"s.lua", "--out", "d", "--slurm-time", "60"}, "are for the job files of --slurm N"},
  };
  for (const auto& [args, expected] : cases) {
    const SweepOptionsResult r = parseSweepOptions(args);
    EXPECT_THAT(r.error, HasSubstr(expected)) << ::testing::PrintToString(args);
  }
  EXPECT_TRUE(parseSweepOptions({"--help"}).options.help);
  EXPECT_TRUE(parseSweepOptions({"merge", "-h"}).options.help);
}

}  // namespace
}  // namespace hemiroll::game
