// game/trial/BotDevice: a bot's pose reaches the servo loop as a device
// reading, through the inverse workspace mapping, held inside the device's
// reach, with a velocity consistent with the poses.

#include "game/trial/BotDevice.h"

#include <gtest/gtest.h>

namespace hemiroll::game {
namespace {

constexpr double kPeriod = 0.001;

haptics::WorkspaceMapping scaledMapping() {
  haptics::WorkspaceMapping m;
  m.scale = 0.5;
  m.offset = Vec3(0.0, 0.0, 0.25);
  return m;
}

TEST(BotDevice, MapsScenePosesBackToDeviceCoordinates) {
  BotDevice device(haptics::DeviceSpec{}, scaledMapping(), kPeriod);
  device.setPose(Vec3(0.015625, -0.03125, 0.28125));
  const haptics::DeviceReading r = device.read(0.0);
  // scene = 0.5 * device + (0, 0, 0.25); values exact in binary, so exact results.
  EXPECT_EQ(r.position, Vec3(0.03125, -0.0625, 0.0625));
  EXPECT_EQ(device.scenePosition(), Vec3(0.015625, -0.03125, 0.28125));
  EXPECT_TRUE(r.fresh);
}

TEST(BotDevice, DerivesTheVelocityFromSuccessivePoses) {
  BotDevice device(haptics::DeviceSpec{}, haptics::WorkspaceMapping{}, kPeriod);
  device.setPose(Vec3(0.0, 0.0, 0.04));
  EXPECT_EQ(device.read(0.0).velocity, Vec3::Zero()) << "no previous pose: at rest";
  device.setPose(Vec3(0.001, 0.0, 0.04));
  // 1 mm in one 1 ms tick is 1 m/s; the division rounds, hence the tolerance.
  EXPECT_NEAR(device.read(0.0).velocity.x(), 1.0, 1e-12);
}

TEST(BotDevice, UsesAGivenVelocityThroughTheMapping) {
  BotDevice device(haptics::DeviceSpec{}, scaledMapping(), kPeriod);
  device.setPose(Vec3(0.0, 0.0, 0.25), Vec3(0.125, 0.0, -0.25));
  EXPECT_EQ(device.read(0.0).velocity, Vec3(0.25, 0.0, -0.5));
}

TEST(BotDevice, StopsAtTheEdgeOfItsWorkspace) {
  haptics::DeviceSpec spec;
  spec.workspaceRadius = 0.1;
  BotDevice device(spec, haptics::WorkspaceMapping{}, kPeriod);
  device.setPose(Vec3(1e300, 0.0, 0.0), Vec3(5.0, 0.0, 0.0));
  const haptics::DeviceReading r = device.read(0.0);
  EXPECT_TRUE(device.limited());
  EXPECT_NEAR(r.position.norm(), 0.1, 1e-15);
  EXPECT_EQ(r.velocity, Vec3::Zero()) << "a stylus at its stop does not move outwards";
  device.setPose(Vec3(0.0, 0.05, 0.0));
  EXPECT_FALSE(device.limited());
}

}  // namespace
}  // namespace hemiroll::game
