#include "engine/haptics/devices/ScriptedDevice.h"

#include <gtest/gtest.h>

#include "engine/haptics/WorkspaceMapping.h"

namespace hemiroll::haptics {
namespace {

TEST(ScriptedDeviceTest, InterpolatesATableAndHoldsItsEnds) {
  ScriptedDevice device(std::vector<PoseSample>{{0.0, Vec3(0, 0, 0)}, {1.0, Vec3(1, 2, 0)}, {2.0, Vec3(1, 2, 4)}});
  EXPECT_EQ(device.read(-1.0).position, Vec3(0, 0, 0));
  const DeviceReading mid = device.read(0.5);
  EXPECT_EQ(mid.position, Vec3(0.5, 1.0, 0.0));
  EXPECT_EQ(mid.velocity, Vec3(1.0, 2.0, 0.0));
  EXPECT_EQ(device.read(1.5).position, Vec3(1, 2, 2));
  EXPECT_EQ(device.read(3.0).position, Vec3(1, 2, 4));
  EXPECT_EQ(device.read(3.0).velocity, Vec3::Zero());
}

TEST(ScriptedDeviceTest, CallbackStallAndError) {
  ScriptedDevice device([](double t) {
    DeviceReading r;
    r.position = Vec3(t, 0, 0);
    return r;
  });
  EXPECT_TRUE(device.read(0.1).fresh);
  device.stallFrom(0.2);
  const DeviceReading stale = device.read(0.3);
  EXPECT_FALSE(stale.fresh);
  EXPECT_EQ(stale.position.x(), 0.1);  // the last sample, repeated
  EXPECT_EQ(device.error(), nullptr);
  device.failWith("unplugged");
  EXPECT_STREQ(device.error(), "unplugged");
}

TEST(ScriptedDeviceTest, RejectsBadTables) {
  EXPECT_THROW(ScriptedDevice(std::vector<PoseSample>{}), std::invalid_argument);
  EXPECT_THROW(ScriptedDevice(std::vector<PoseSample>{{1.0, Vec3::Zero()}, {1.0, Vec3::Zero()}}),
               std::invalid_argument);
}

TEST(WorkspaceMappingTest, MapsAndKeepsPowerBalanced) {
  WorkspaceMapping map;
  map.scale = 0.5;
  map.offset = Vec3(0.0, 0.0, 0.04);
  EXPECT_EQ(map.positionToScene(Vec3(0.2, 0.0, 0.0)), Vec3(0.1, 0.0, 0.04));
  const Vec3 vDevice(0.3, -0.1, 0.2), fScene(1.0, 2.0, -0.5);
  // F_d . v_d == F_s . v_s (scale 0.5 is exact in binary).
  EXPECT_EQ(map.forceToDevice(fScene).dot(vDevice), fScene.dot(map.velocityToScene(vDevice)));
}

}  // namespace
}  // namespace hemiroll::haptics
