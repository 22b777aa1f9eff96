// game/trial/HandoffBotDevice: the bot's poses reach the servo thread through
// a latest-value hand-over and are extrapolated to each tick's time, held
// after kMaxExtrapolation, and marked stale after kStaleAfter.

#include "game/trial/HandoffBotDevice.h"

#include <gtest/gtest.h>

#include <thread>

namespace hemiroll::game {
namespace {

TEST(HandoffBotDevice, NothingPublishedIsNotFresh) {
  HandoffBotDevice device(haptics::DeviceSpec{}, haptics::WorkspaceMapping{});
  EXPECT_FALSE(device.read(0.0).fresh);
}

TEST(HandoffBotDevice, ExtrapolatesTheLatestPoseToTheTickTime) {
  HandoffBotDevice device(haptics::DeviceSpec{}, haptics::WorkspaceMapping{});
  device.publish(1.0, Vec3(0.0, 0.0, 0.04), Vec3(0.5, 0.0, 0.0));
  const haptics::DeviceReading r = device.read(1.004);
  // 0.5 m/s for 4 ms = 2 mm; the sums round in the last bits.
  EXPECT_NEAR(r.position.x(), 0.002, 1e-15);
  EXPECT_EQ(r.velocity, Vec3(0.5, 0.0, 0.0));
  EXPECT_TRUE(r.fresh);
}

TEST(HandoffBotDevice, DerivesTheVelocityFromPublishedPoses) {
  HandoffBotDevice device(haptics::DeviceSpec{}, haptics::WorkspaceMapping{});
  device.publish(0.0, Vec3(0.0, 0.0, 0.04));
  device.publish(0.002, Vec3(0.001, 0.0, 0.04));  // 1 mm in 2 ms
  EXPECT_NEAR(device.read(0.002).velocity.x(), 0.5, 1e-12);
}

TEST(HandoffBotDevice, HoldsAfterTheExtrapolationLimitAndGoesStale) {
  HandoffBotDevice device(haptics::DeviceSpec{}, haptics::WorkspaceMapping{});
  device.publish(0.0, Vec3(0.0, 0.0, 0.04), Vec3(1.0, 0.0, 0.0));
  const double limit = HandoffBotDevice::kMaxExtrapolation;
  const haptics::DeviceReading late = device.read(limit + 0.01);
  EXPECT_NEAR(late.position.x(), limit, 1e-15) << "held where the extrapolation stopped";
  EXPECT_EQ(late.velocity, Vec3::Zero());
  EXPECT_TRUE(late.fresh);
  EXPECT_FALSE(device.read(HandoffBotDevice::kStaleAfter + 0.001).fresh);
}

TEST(HandoffBotDevice, AcrossThreadsTheReaderSeesWholeSamples) {
  // A writer publishes x = y = i; a torn read would show x != y.
  HandoffBotDevice device(haptics::DeviceSpec{}, haptics::WorkspaceMapping{});
  std::thread writer([&] {
    for (int i = 1; i <= 20000; ++i) device.publish(1e-3 * i, Vec3(1e-6 * i, 1e-6 * i, 0.0), Vec3::Zero());
  });
  for (int k = 0; k < 20000; ++k) {
    const haptics::DeviceReading r = device.read(0.0);
    EXPECT_EQ(r.position.x(), r.position.y());  // also before the first sample: both zero
  }
  writer.join();
}

}  // namespace
}  // namespace hemiroll::game
