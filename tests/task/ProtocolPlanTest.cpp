// engine/task/ProtocolPlan: a protocol expanded into its trials - counts,
// block order, deterministic per seed, shuffled differently per seed.

#include "engine/task/ProtocolPlan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

namespace hemiroll::task {
namespace {

BlockDef block(int conditions, int repetitions, bool randomise) {
  BlockDef b;
  for (int c = 1; c <= conditions; ++c) {
    ConditionDef condition;
    // Appended, not "c" + to_string(c): GCC 12 warns on the latter (-Wrestrict, a false positive).
    condition.label = "c";
    condition.label += std::to_string(c);
    b.conditions.push_back(condition);
  }
  b.repetitions = repetitions;
  b.randomise = randomise;
  return b;
}

ProtocolDef protocol(std::vector<BlockDef> blocks) {
  ProtocolDef p;
  p.experiment = "e";
  p.blocks = std::move(blocks);
  return p;
}

// (block, condition, repetition) per trial: the order a plan runs in.
std::vector<std::tuple<int, int, int>> order(const ProtocolPlan& plan) {
  std::vector<std::tuple<int, int, int>> out;
  for (const PlannedTrial& t : plan.trials) out.emplace_back(t.block, t.condition, t.repetition);
  return out;
}

TEST(ProtocolPlan, CountsIndicesAndTheOrderOfAnUnshuffledBlock) {
  const ProtocolPlan plan = expandProtocol(protocol({block(3, 2, false), block(1, 5, false)}), 0);
  ASSERT_EQ(plan.trials.size(), 3u * 2u + 5u);
  // Passes through the conditions: c1 c2 c3, c1 c2 c3; then block 2.
  const std::vector<std::tuple<int, int, int>> expected = {{1, 1, 1}, {1, 2, 1}, {1, 3, 1}, {1, 1, 2}, {1, 2, 2}, {1, 3, 2},
                                                           {2, 1, 1}, {2, 1, 2}, {2, 1, 3}, {2, 1, 4}, {2, 1, 5}};
  EXPECT_EQ(order(plan), expected);
  for (std::size_t i = 0; i < plan.trials.size(); ++i) {
    EXPECT_EQ(plan.trials[i].index, static_cast<int>(i) + 1);
    EXPECT_EQ(plan.trials[i].trialInBlock, plan.trials[i].block == 1 ? static_cast<int>(i) + 1 : static_cast<int>(i) - 5);
  }
}

TEST(ProtocolPlan, TheSameProtocolAndSeedGiveTheSamePlan) {
  const ProtocolDef p = protocol({block(9, 2, true), block(2, 3, true), block(1, 15, false)});
  const ProtocolPlan a = expandProtocol(p, 2009);
  const ProtocolPlan b = expandProtocol(p, 2009);
  ASSERT_EQ(a.trials.size(), b.trials.size());
  for (std::size_t i = 0; i < a.trials.size(); ++i) {
    EXPECT_EQ(a.trials[i].block, b.trials[i].block);
    EXPECT_EQ(a.trials[i].condition, b.trials[i].condition);
    EXPECT_EQ(a.trials[i].repetition, b.trials[i].repetition);
    EXPECT_EQ(a.trials[i].seed, b.trials[i].seed);
  }
}

// The algorithm is documented (PROTOCOLS.md) so that a plan can be
// reproduced anywhere; changing it would silently change the order of every
// running study's remaining sessions. This pins one small plan.
TEST(ProtocolPlan, TheShuffleIsPinned) {
  const ProtocolPlan plan = expandProtocol(protocol({block(4, 1, true)}), 0);
  std::vector<int> conditions;
  for (const PlannedTrial& t : plan.trials) conditions.push_back(t.condition);
  EXPECT_EQ(conditions, (std::vector<int>{3, 1, 2, 4}));
}

TEST(ProtocolPlan, DifferentSeedsShuffleDifferently) {
  const ProtocolDef p = protocol({block(9, 2, true)});  // 18 trials: 18!/2^9 orders
  std::set<std::vector<std::tuple<int, int, int>>> orders;
  for (std::uint64_t seed = 0; seed < 8; ++seed) orders.insert(order(expandProtocol(p, seed)));
  // Two equal orders among 8 draws from ~1.2e13 would be a broken shuffle.
  EXPECT_EQ(orders.size(), 8u);
}

TEST(ProtocolPlan, AShuffledBlockHoldsEveryConditionOfEveryPassOnce) {
  const ProtocolPlan plan = expandProtocol(protocol({block(9, 2, true)}), 42);
  std::map<std::pair<int, int>, int> seen;  // (condition, repetition) -> count
  for (const PlannedTrial& t : plan.trials) ++seen[{t.condition, t.repetition}];
  EXPECT_EQ(seen.size(), 18u);
  for (const auto& [key, count] : seen) EXPECT_EQ(count, 1);
  // ... and is not left in order (the chance of the identity is 1/18!).
  std::vector<std::tuple<int, int, int>> sorted = order(plan);
  std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) {
    return std::make_pair(std::get<2>(a), std::get<1>(a)) < std::make_pair(std::get<2>(b), std::get<1>(b));
  });
  EXPECT_NE(order(plan), sorted);
}

TEST(ProtocolPlan, BlocksStayInOrderAndDoNotDependOnEachOthersShuffling) {
  const ProtocolPlan shuffled = expandProtocol(protocol({block(5, 2, true), block(4, 2, true)}), 7);
  const ProtocolPlan plain = expandProtocol(protocol({block(5, 2, false), block(4, 2, true)}), 7);
  for (std::size_t i = 1; i < shuffled.trials.size(); ++i)
    EXPECT_LE(shuffled.trials[i - 1].block, shuffled.trials[i].block);
  // Block 2's order and seeds are the same whether block 1 is shuffled or not.
  for (std::size_t i = 10; i < 18; ++i) {
    EXPECT_EQ(shuffled.trials[i].condition, plain.trials[i].condition);
    EXPECT_EQ(shuffled.trials[i].seed, plain.trials[i].seed);
  }
}

TEST(ProtocolPlan, EveryTrialHasItsOwnSeedALuaIntegerCanHold) {
  const ProtocolPlan plan = expandProtocol(protocol({block(3, 10, true)}), 3);
  std::set<std::uint64_t> seeds;
  for (const PlannedTrial& t : plan.trials) {
    EXPECT_LE(t.seed, 0x7fffffffffffffffULL);
    seeds.insert(t.seed);
  }
  EXPECT_EQ(seeds.size(), plan.trials.size());
  EXPECT_NE(expandProtocol(protocol({block(3, 10, true)}), 4).trials[0].seed, plan.trials[0].seed);
}

TEST(ProtocolPlan, TheBreakBeforeATrialIsThePreviousBlocksOnItsFirstTrial) {
  ProtocolDef p = protocol({block(1, 2, false), block(1, 2, false), block(1, 1, false)});
  p.blocks[0].breakAfter = BreakDef{"rest", 60.0, false};
  const ProtocolPlan plan = expandProtocol(p, 0);
  std::vector<const BreakDef*> breaks;
  for (const PlannedTrial& t : plan.trials) breaks.push_back(ProtocolPlan::breakBefore(p, t));
  EXPECT_EQ(breaks, (std::vector<const BreakDef*>{nullptr, nullptr, &*p.blocks[0].breakAfter, nullptr, nullptr}));
  EXPECT_EQ(&ProtocolPlan::conditionOf(p, plan.trials[2]), &p.blocks[1].conditions[0]);
}


TEST(ProtocolPlanTest, ABlockOrderMovesWholeBlocksAndKeepsTheirTrialsAndSeeds) {
  ProtocolDef p = protocol({block(1, 2, false), block(3, 1, true), block(2, 2, true)});
  p.counterbalanced = {1, 2};  // two blocks: orders 1 (as written) and 2 (swapped)
  const ProtocolPlan first = expandProtocol(p, 7, 1);
  const ProtocolPlan second = expandProtocol(p, 7, 2);
  EXPECT_EQ(first.trials.size(), second.trials.size());
  // The plan of order 1 is the plan without counterbalancing.
  EXPECT_EQ(order(first), order(expandProtocol(protocol({block(1, 2, false), block(3, 1, true), block(2, 2, true)}), 7)));
  std::map<int, std::vector<std::pair<int, std::uint64_t>>> byBlock1, byBlock2;  // defined block -> (condition, seed)
  for (const PlannedTrial& t : first.trials) byBlock1[t.definedBlock].emplace_back(t.condition, t.seed);
  for (const PlannedTrial& t : second.trials) byBlock2[t.definedBlock].emplace_back(t.condition, t.seed);
  EXPECT_EQ(byBlock1, byBlock2);  // a block plays the same trials wherever it is placed
  std::vector<int> places;
  for (const PlannedTrial& t : second.trials) {
    EXPECT_EQ(t.block, t.definedBlock == 1 ? 1 : (t.definedBlock == 2 ? 3 : 2));
    EXPECT_EQ(&ProtocolPlan::blockOf(p, t), &p.blocks[static_cast<std::size_t>(t.definedBlock - 1)]);
  }
  for (std::size_t i = 0; i < second.trials.size(); ++i) EXPECT_EQ(second.trials[i].index, static_cast<int>(i) + 1);
}

}  // namespace
}  // namespace hemiroll::task
