// engine/script/ProtocolDef: overrides applied to a level's coupling and
// time limit, the names of couplings, and folder-safe ids.

#include "engine/script/ProtocolDef.h"

#include <gtest/gtest.h>

#include <vector>

namespace hemiroll::script {
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

}  // namespace
}  // namespace hemiroll::script
