#include "engine/haptics/devices/ReplayDevice.h"

#include <gtest/gtest.h>

namespace hemiroll::haptics {
namespace {

std::vector<TickInput> inputs(int n) {
  std::vector<TickInput> v;
  for (int k = 1; k <= n; ++k) {
    TickInput in;
    in.tick = static_cast<std::uint64_t>(k);
    in.position = {0.01 * k, 0.0, -0.01 * k};
    in.velocity = {1.0 * k, 2.0, 3.0};
    in.buttons = static_cast<std::uint32_t>(k);
    in.fresh = k % 2 == 1;
    v.push_back(in);
  }
  return v;
}

TEST(ReplayDeviceTest, PlaysEveryInputInOrderWhateverTheTime) {
  ReplayDevice device(inputs(3));
  for (int k = 1; k <= 3; ++k) {
    const DeviceReading r = device.read(100.0 - k);  // time is ignored: the k-th read is the k-th input
    EXPECT_EQ(r.position, Vec3(0.01 * k, 0.0, -0.01 * k));
    EXPECT_EQ(r.velocity, Vec3(1.0 * k, 2.0, 3.0));
    EXPECT_EQ(r.buttons, static_cast<std::uint32_t>(k));
    EXPECT_EQ(r.fresh, k % 2 == 1);
    EXPECT_EQ(device.error(), nullptr);
  }
  EXPECT_TRUE(device.finished());
}

TEST(ReplayDeviceTest, AfterTheEndItReportsAnErrorAndStaleData) {
  ReplayDevice device(inputs(1));
  device.read(0.0);
  const DeviceReading r = device.read(0.001);
  EXPECT_FALSE(r.fresh);
  EXPECT_EQ(r.position, Vec3(0.01, 0.0, -0.01));  // the last pose held
  ASSERT_NE(device.error(), nullptr);
  EXPECT_STREQ(device.error(), "replay log ended");
  ReplayDevice empty({});
  EXPECT_FALSE(empty.read(0.0).fresh);
  EXPECT_NE(empty.error(), nullptr);
}

}  // namespace
}  // namespace hemiroll::haptics
