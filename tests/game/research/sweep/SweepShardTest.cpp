// game/research/sweep/SweepShard: "i/N" read strictly; the shards of a split hold
// every point exactly once; file stems.

#include "game/research/sweep/SweepShard.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

namespace hemiroll::game {
namespace {

using ::testing::ElementsAre;

TEST(SweepShard, ParsesIOverN) {
  const auto s = SweepShard::parse("3/8");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->index, 3);
  EXPECT_EQ(s->count, 8);
  EXPECT_EQ(s->label(), "3/8");
  EXPECT_EQ(s->stem(), "part-3-of-8");
  EXPECT_EQ(SweepShard::parse("0/1")->stem(), "sweep");
  for (const char* bad : {"", "1", "8/8", "9/8", "-1/4", "1/0", "a/4", "1/4/2", "1 /4", "1/1000001"})
    EXPECT_FALSE(SweepShard::parse(bad)) << bad;
}

TEST(SweepShard, ShardsPartitionThePoints) {
  for (const long long total : {0LL, 1LL, 7LL, 100LL}) {
    for (const long long n : {1LL, 2LL, 3LL, 16LL}) {
      std::vector<int> seen(static_cast<std::size_t>(total), 0);
      for (long long i = 0; i < n; ++i) {
        const SweepShard s{i, n};
        const std::vector<long long> points = s.points(total);
        EXPECT_EQ(static_cast<long long>(points.size()), s.size(total));
        for (const long long p : points) ++seen[static_cast<std::size_t>(p)];
      }
      for (const int c : seen) EXPECT_EQ(c, 1) << total << " " << n;
    }
  }
  EXPECT_THAT((SweepShard{1, 3}.points(8)), ElementsAre(1, 4, 7));
}

}  // namespace
}  // namespace hemiroll::game
