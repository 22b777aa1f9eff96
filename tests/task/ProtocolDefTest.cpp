// engine/task/ProtocolDef: overrides applied to a level's coupling and
// time limit, the names of couplings, and folder-safe ids.

#include "engine/task/ProtocolDef.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

namespace hemiroll::task {
namespace {

physics::CouplingDef levelCoupling() {
  physics::CouplingDef c;
  c.method = physics::ForceMethod::M2;
  c.stiffness = 100.0;
  c.damping = 4.0;
  c.alpha = 1.5;
  return c;
}

TEST(ProtocolDef, NoOverridesKeepTheLevelsCoupling) {
  const physics::CouplingDef c = overriddenCoupling({}, levelCoupling());
  EXPECT_EQ(c.method, physics::ForceMethod::M2);
  EXPECT_EQ(c.stiffness, 100.0);
  EXPECT_EQ(c.damping, 4.0);
  EXPECT_EQ(c.alpha, 1.5);
  EXPECT_FALSE(c.visualOnly);
}

TEST(ProtocolDef, OverridesReplaceOnlyWhatTheyGive) {
  TrialOverrides o;
  o.method = "M3";
  o.alpha = 4.0;
  const physics::CouplingDef c = overriddenCoupling(o, levelCoupling());
  EXPECT_EQ(c.method, physics::ForceMethod::M3);
  EXPECT_EQ(c.alpha, 4.0);
  EXPECT_EQ(c.stiffness, 100.0);
  EXPECT_EQ(c.damping, 4.0);
}

// "visual" is what a level file means by it: M3's gains drive the model and
// the device renders nothing.
TEST(ProtocolDef, VisualIsM3WithoutRenderedForceAndAnotherMethodClearsIt) {
  TrialOverrides visual;
  visual.method = "visual";
  const physics::CouplingDef v = overriddenCoupling(visual, levelCoupling());
  EXPECT_TRUE(v.visualOnly);
  EXPECT_EQ(v.method, physics::ForceMethod::M3);
  EXPECT_EQ(couplingMethodName(v), "visual");
  TrialOverrides m1;
  m1.method = "M1";
  const physics::CouplingDef back = overriddenCoupling(m1, v);
  EXPECT_FALSE(back.visualOnly);
  EXPECT_EQ(couplingMethodName(back), "M1");
}

TEST(ProtocolDef, ApplyingOverridesSetsTheTimeLimitToo) {
  LevelDef level;
  level.coupling = levelCoupling();
  TrialOverrides o;
  o.stiffness = 250.0;
  o.timeLimit = 30.0;
  applyTrialOverrides(o, level);
  EXPECT_EQ(level.coupling.stiffness, 250.0);
  EXPECT_EQ(level.task.timeLimit, 30.0);
  TrialOverrides none;
  applyTrialOverrides(none, level);
  EXPECT_EQ(level.task.timeLimit, 30.0);
}

TEST(ProtocolDef, FolderNamesAreLettersDigitsDashAndUnderscore) {
  EXPECT_TRUE(isFolderName("p01"));
  EXPECT_TRUE(isFolderName("svinin2009-two_days"));
  EXPECT_TRUE(isFolderName(std::string(64, 'a')));
  for (const std::string& bad : std::vector<std::string>{"", "..", "a/b", "a.b", "a b", "ü", std::string(65, 'a')})
    EXPECT_FALSE(isFolderName(bad)) << bad;
}


// A balanced Latin square: every item once per row and per position, and
// every ordered pair of different items adjacent equally often (once over
// the n rows of an even n, twice over the 2n rows of an odd n).
TEST(ProtocolDefTest, WilliamsSquareIsALatinSquareBalancedForNeighbours) {
  for (int n = 2; n <= 7; ++n) {
    const auto rows = williamsSquare(n);
    const std::size_t expectedRows = static_cast<std::size_t>(n % 2 == 0 ? n : 2 * n);
    ASSERT_EQ(rows.size(), expectedRows) << n;
    std::vector<std::vector<int>> inPosition(static_cast<std::size_t>(n), std::vector<int>(static_cast<std::size_t>(n), 0));
    std::vector<std::vector<int>> follows(static_cast<std::size_t>(n), std::vector<int>(static_cast<std::size_t>(n), 0));
    for (const auto& row : rows) {
      ASSERT_EQ(row.size(), static_cast<std::size_t>(n));
      std::vector<int> sorted = row;
      std::sort(sorted.begin(), sorted.end());
      for (int i = 0; i < n; ++i) EXPECT_EQ(sorted[static_cast<std::size_t>(i)], i) << "row is no permutation, n " << n;
      for (int p = 0; p < n; ++p) ++inPosition[static_cast<std::size_t>(p)][static_cast<std::size_t>(row[static_cast<std::size_t>(p)])];
      for (int p = 0; p + 1 < n; ++p)
        ++follows[static_cast<std::size_t>(row[static_cast<std::size_t>(p)])][static_cast<std::size_t>(row[static_cast<std::size_t>(p) + 1])];
    }
    const int perCell = static_cast<int>(expectedRows) / n;
    const int perPair = n % 2 == 0 ? 1 : 2;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        EXPECT_EQ(inPosition[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)], perCell) << n;
        if (a != b) {
          EXPECT_EQ(follows[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)], perPair) << n << ": " << a << "->" << b;
        }
      }
  }
  EXPECT_EQ(williamsSquare(4)[0], (std::vector<int>{0, 1, 3, 2}));
}

TEST(ProtocolDefTest, BlockSequencePermutesOnlyTheCounterbalancedBlocksAmongTheirPlaces) {
  ProtocolDef p;
  p.blocks.resize(5);
  p.counterbalanced = {1, 2, 4};  // three blocks: 6 orders
  EXPECT_EQ(p.orderCount(), 6);
  std::set<std::vector<int>> seen;
  for (int order = 1; order <= 6; ++order) {
    const std::vector<int> s = p.blockSequence(order);
    ASSERT_EQ(s.size(), 5u);
    EXPECT_EQ(s[0], 0);
    EXPECT_EQ(s[3], 3);
    EXPECT_EQ((std::set<int>{s[1], s[2], s[4]}), (std::set<int>{1, 2, 4}));
    seen.insert(s);
  }
  EXPECT_EQ(seen.size(), 6u);  // 3! orders, each once
  EXPECT_EQ(p.blockSequence(1), (std::vector<int>{0, 1, 2, 3, 4}));  // row 1 of the square is the file's order
  p.counterbalanced.clear();
  EXPECT_EQ(p.orderCount(), 1);
  EXPECT_EQ(p.blockSequence(3), (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(ProtocolDefTest, AGroupsChangesWinInItsBlockAndRebuildADefaultLabel) {
  ConditionDef c;
  c.level = "levels/x.lua";
  c.overrides.stiffness = 250.0;
  c.label = defaultConditionLabel(c.overrides, c.level);
  GroupDef g;
  g.name = "guided";
  GroupChange change;
  change.block = 1;
  GuidanceSpec guidance;
  guidance.kind = "autopilot";
  guidance.stiffness = 300.0;
  change.overrides.guidance = guidance;
  change.overrides.stiffness = 200.0;
  g.changes.push_back(change);
  const ConditionDef inBlock1 = conditionInGroup(c, 1, &g);
  EXPECT_EQ(inBlock1.overrides.stiffness, 200.0);
  ASSERT_TRUE(inBlock1.overrides.guidance);
  EXPECT_EQ(inBlock1.overrides.guidance->stiffness, 300.0);
  EXPECT_EQ(inBlock1.label, "kr 200 guided");
  const ConditionDef inBlock0 = conditionInGroup(c, 0, &g);  // the group changes nothing there
  EXPECT_EQ(inBlock0.overrides.stiffness, 250.0);
  EXPECT_EQ(inBlock0.label, "kr 250");
  c.label = "mine";
  c.labelGiven = true;
  EXPECT_EQ(conditionInGroup(c, 1, &g).label, "mine");
  EXPECT_EQ(conditionInGroup(c, 1, nullptr).overrides.stiffness, 250.0);
}

}  // namespace
}  // namespace hemiroll::task
