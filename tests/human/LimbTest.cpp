// engine/human/Limb: the hand follows its intent through the muscles' spring
// and damper, and a force on it displaces it by F / k at rest.

#include "engine/human/Limb.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace hemiroll::human
