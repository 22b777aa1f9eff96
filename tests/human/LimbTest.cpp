// engine/human/Limb: the hand follows its intent through the muscles' spring
// and damper, and a force on it displaces it by F / k at rest; on a force
// device the arm is the co-contracted one.

#include "engine/human/Limb.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hemiroll::human {
namespace {

using physics::Vec3;

TEST(Limb, AtRestUnderAForceTheHandStandsOffItsIntentByForceOverStiffness) {
  LimbDef def;
  Limb limb(def);
  limb.reset(Vec3::Zero());
  const Vec3 force(1.5, -0.6, 0.3);
  for (int i = 0; i < 5000; ++i) limb.step(Vec3::Zero(), Vec3::Zero(), force, 0.001);
  EXPECT_NEAR((limb.position() - force / def.stiffness).norm(), 0.0, 1e-9);
  EXPECT_LT(limb.velocity().norm(), 1e-9);
}

TEST(Limb, WithoutAForceItTracksAStillIntentWithoutOvershootingMuch) {
  LimbDef def;  // damped at 0.8 of critical
  Limb limb(def);
  limb.reset(Vec3::Zero());
  const Vec3 intent(0.01, 0.0, 0.0);
  double most = 0.0;
  for (int i = 0; i < 2000; ++i) {
    limb.step(intent, Vec3::Zero(), Vec3::Zero(), 0.001);
    most = std::max(most, limb.position().x());
  }
  EXPECT_NEAR(limb.position().x(), 0.01, 1e-8);
  EXPECT_LT(most, 0.01 * 1.03);  // exp(-pi z / sqrt(1 - z^2)) = 1.7 % overshoot at z = 0.79
}

// On a force device the arm is co-contracted (docs/HUMAN_MODEL.md "The arm
// on a force device"): 1000 N/m, the relaxed mass, the relaxed damping
// ratio; a mouse, the mouse-hand and the relaxed-arm setting keep the
// relaxed limb.
TEST(Limb, TheCoContractedArmHasTheDeclaredStiffnessAndHoldsOnlyAForceDevice) {
  HumanDef def;
  def.device = HandDevice::Haptic;
  const LimbDef& held = holdingLimb(def);
  EXPECT_EQ(held.stiffness, 1000.0);
  EXPECT_EQ(held.mass, def.limb.mass);
  const auto dampingRatio = [](const LimbDef& l) { return l.damping / (2.0 * std::sqrt(l.stiffness * l.mass)); };
  // 27.4 N s/m is 15 x sqrt(1000 / 300) = 27.386 rounded to 0.1 N s/m.
  EXPECT_NEAR(dampingRatio(held), dampingRatio(def.limb), 0.001);

  Limb limb(held);
  limb.reset(Vec3::Zero());
  const Vec3 force(1.5, -0.6, 0.3);  // the same in every direction
  for (int i = 0; i < 5000; ++i) limb.step(Vec3::Zero(), Vec3::Zero(), force, 0.001);
  EXPECT_NEAR((limb.position() - force / 1000.0).norm(), 0.0, 1e-9);

  for (const HandDevice device : {HandDevice::Mouse, HandDevice::MouseHand}) {
    def.device = device;
    EXPECT_EQ(holdingLimb(def).stiffness, 300.0) << handDeviceName(device);
  }
  def.device = HandDevice::Haptic;
  def.coContracts = false;
  EXPECT_EQ(holdingLimb(def).stiffness, 300.0);
}

}  // namespace
}  // namespace hemiroll::human
