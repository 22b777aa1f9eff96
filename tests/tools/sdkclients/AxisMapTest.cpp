// tools/sdkclients/AxisMap: each SDK's frame and unit against the bridge's
// (x right, y away from the user, z up; metres).

#include "tools/sdkclients/AxisMap.h"

#include <gtest/gtest.h>

#include <random>

namespace hemiroll::sdkclients {
namespace {

TEST(AxisMapTest, EachSdkFrameLandsOnTheBridgesAxes) {
  // OpenHaptics: 10 mm right, 20 mm up, 30 mm towards the user.
  const Vec3 hd = openHapticsAxes().positionToBridge({10.0, 20.0, 30.0});
  EXPECT_DOUBLE_EQ(hd[0], 0.010);   // right
  EXPECT_DOUBLE_EQ(hd[1], -0.030);  // towards the user is -away
  EXPECT_DOUBLE_EQ(hd[2], 0.020);   // up
  // Force Dimension: 0.01 m towards the user, 0.02 m right, 0.03 m up.
  const Vec3 fd = forceDimensionAxes().positionToBridge({0.01, 0.02, 0.03});
  EXPECT_DOUBLE_EQ(fd[0], 0.02);
  EXPECT_DOUBLE_EQ(fd[1], -0.01);
  EXPECT_DOUBLE_EQ(fd[2], 0.03);
  // libnifalcon: the workspace's centre (0.11 m out) is the bridge's origin.
  const Vec3 falcon = libnifalconAxes().positionToBridge({0.0, 0.0, 0.11});
  for (double c : falcon) EXPECT_NEAR(c, 0.0, 1e-15);
  for (const AxisMap& m : {openHapticsAxes(), forceDimensionAxes(), libnifalconAxes()}) EXPECT_FALSE(m.problem());
}

// A force returned to the device must do the same work on the same motion
// in both frames: F_bridge . v_bridge = F_device . v_device [W], with the
// velocity in the device's unit converted. This holds only when the force's
// map is the transpose of the motion's, whatever the permutation and signs.
TEST(AxisMapTest, ForcesGoBackByTheTransposeSoPowerIsTheSameInBothFrames) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const AxisMap& m : {openHapticsAxes(), forceDimensionAxes(), libnifalconAxes()}) {
    for (int trial = 0; trial < 100; ++trial) {
      const Vec3 vDevice{u(rng), u(rng), u(rng)}, fBridge{u(rng), u(rng), u(rng)};
      const Vec3 vBridge = m.velocityToBridge(vDevice), fDevice = m.forceToDevice(fBridge);
      double bridgePower = 0.0, devicePower = 0.0;
      for (int i = 0; i < 3; ++i) {
        bridgePower += fBridge[i] * vBridge[i];
        devicePower += fDevice[i] * vDevice[i] * m.metresPerUnit;
      }
      EXPECT_NEAR(bridgePower, devicePower, 1e-15);
    }
  }
}

TEST(AxisMapTest, AMapThatIsNotASignedPermutationIsRefused) {
  AxisMap m;
  m.source = {0, 0, 2};
  EXPECT_EQ(*m.problem(), "an axis map takes each device axis exactly once");
  m = AxisMap{};
  m.sign = {1, 0, 1};
  EXPECT_TRUE(m.problem());
  m = AxisMap{};
  m.metresPerUnit = 0.0;
  EXPECT_TRUE(m.problem());
}

}  // namespace
}  // namespace hemiroll::sdkclients
