// game/trial/DeviceProfiles: a profile found by name, what it becomes in a
// trial (spec and safety limits), and the one-sentence refusal of a
// coupling it cannot render.

#include "game/trial/DeviceProfiles.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "engine/script/DeviceProfileLoader.h"
#include "engine/script/ScriptError.h"
#include "tests/support/ErrorMessage.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

const std::string kSource = HEMIROLL_SOURCE_DIR;

task::DeviceProfileDef shipped(const std::string& name) {
  return script::DeviceProfileLoader().loadFile(kSource + "/devices/" + name + ".lua");
}

TEST(DeviceProfiles, TheSpecIsTheProfilesPeakStiffnessAndInnerReach) {
  const task::DeviceProfileDef touch = shipped("touch");
  const haptics::DeviceSpec spec = deviceSpecOf(touch);
  EXPECT_STREQ(spec.name, "3D Systems Touch");
  EXPECT_EQ(spec.maxForce, touch.peakForceN);
  EXPECT_EQ(spec.maxStiffness, touch.maxStiffnessNPerM);
  EXPECT_EQ(spec.workspaceRadius, 0.5 * touch.workspaceDepthM);  // the Touch's smallest extent
  EXPECT_TRUE(spec.hasForceOutput);
}

TEST(DeviceProfiles, TheSafetyLimitsAreTheProfiles) {
  const task::DeviceProfileDef falcon = shipped("falcon");
  haptics::SafetyDef base;
  base.maxDeviceSpeed = 1.5;  // what the profile does not set is kept
  const haptics::SafetyDef s = safetyOf(falcon, base);
  EXPECT_EQ(s.maxForceRate, falcon.maxForceRateNPerS);
  EXPECT_EQ(s.workspaceHalfWidth, 0.5 * falcon.workspaceWidthM);
  EXPECT_EQ(s.workspaceHalfDepth, 0.5 * falcon.workspaceDepthM);
  EXPECT_EQ(s.workspaceHalfHeight, 0.5 * falcon.workspaceHeightM);
  EXPECT_EQ(s.workspaceMargin, falcon.workspaceMarginM);
  EXPECT_EQ(s.continuousForce, falcon.continuousForceN);
  EXPECT_EQ(s.aboveContinuousLimit, falcon.aboveContinuousLimitS);
  EXPECT_EQ(s.maxDeviceSpeed, 1.5);
}

TEST(DeviceProfiles, ACouplingTooStiffIsRefusedInOneSentenceNamingBoth) {
  const task::DeviceProfileDef touch = shipped("touch");
  physics::CouplingDef c;
  c.method = physics::ForceMethod::M1;
  c.stiffness = 1500.0;
  const std::string refusal = couplingRefusal(touch, c, "levels/stiff.lua");
  EXPECT_THAT(refusal, HasSubstr("levels/stiff.lua"));
  EXPECT_THAT(refusal, HasSubstr("1500 N/m"));
  EXPECT_THAT(refusal, HasSubstr("3D Systems Touch"));
  EXPECT_THAT(refusal, HasSubstr("1020 N/m"));
  EXPECT_EQ(refusal.find(". "), std::string::npos) << "one sentence: " << refusal;
  c.stiffness = 1000.0;
  EXPECT_EQ(couplingRefusal(touch, c, "levels/soft.lua"), "");
}

TEST(DeviceProfiles, M3sAlphaCountsInTheStiffestDirection) {
  const task::DeviceProfileDef touch = shipped("touch");
  physics::CouplingDef c;
  c.method = physics::ForceMethod::M3;
  c.stiffness = 600.0;
  c.alpha = 2.0;  // 1200 N/m along the normal
  EXPECT_THAT(couplingRefusal(touch, c, "lv.lua"), HasSubstr("1200 N/m (k_r 600 N/m times alpha 2)"));
  c.visualOnly = true;  // nothing rendered: nothing to refuse
  EXPECT_EQ(couplingRefusal(touch, c, "lv.lua"), "");
}

TEST(DeviceProfiles, DampingIsCheckedWhereTheProfileGivesAMaximum) {
  task::DeviceProfileDef p = shipped("generic");
  physics::CouplingDef c;
  c.stiffness = 100.0;
  c.damping = 50.0;
  EXPECT_EQ(couplingRefusal(p, c, "lv.lua"), "");  // no maximum published: not checked
  p.maxDampingNsPerM = 20.0;
  EXPECT_THAT(couplingRefusal(p, c, "lv.lua"), HasSubstr("damping k_v of 50 N s/m, above the generic haptic device's"));
}

TEST(DeviceProfiles, FoundByNameInTheDevicesFolder) {
  ::setenv("HEMIROLL_DEVICES", (kSource + "/devices").c_str(), 1);
  EXPECT_EQ(loadDeviceProfile("omega3").model, "Force Dimension omega.3");
  EXPECT_EQ(loadDeviceProfile(kSource + "/devices/touch_x.lua").name, "touch_x");
  const std::string e = test::messageOf<script::ScriptError>([] { loadDeviceProfile("phantom9000"); });
  EXPECT_THAT(e, HasSubstr("unknown device profile 'phantom9000'"));
  EXPECT_THAT(e, HasSubstr("known profiles: falcon, generic, inverse3, omega3, omega6, touch, touch_x"));
  ::unsetenv("HEMIROLL_DEVICES");
}

}  // namespace
}  // namespace hemiroll::game
