// tools/sdkclients/BridgeLink: what a client applies from what the bridge
// sends, with the clock given by the test (exchange takes "now").

#include "tools/sdkclients/BridgeLink.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "tests/tools/sdkclients/FakeBridge.h"

namespace hemiroll::sdkclients {
namespace {

using haptics::udp::BridgeStatus;
using test::FakeBridge;

constexpr std::int64_t kMs = 1'000'000;

// Exchanges until the bridge has answered (loopback: well under 100 ms).
Vec3 exchangeUntilAnswered(BridgeLink& link, const DeviceSample& s, std::int64_t now) {
  for (int i = 0; i < 200 && link.counters().forcesReceived == 0; ++i) {
    link.exchange(s, now);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return link.exchange(s, now);  // the answer to the last state is taken now at the latest
}

BridgeLinkDef linkTo(const FakeBridge& bridge, double maxForce) {
  BridgeLinkDef def;
  def.port = bridge.port();
  def.axes = openHapticsAxes();
  def.maxForce = maxForce;
  return def;
}

TEST(BridgeLinkTest, SendsTheSampleInTheBridgesFrameAndAppliesTheForceInTheDevices) {
  FakeBridge bridge({0.1, 0.2, 0.3});
  BridgeLink link(linkTo(bridge, 3.0));
  ASSERT_EQ(link.open(), "");
  DeviceSample s;
  s.position = {10.0, 20.0, 30.0};  // mm, OpenHaptics' frame
  s.velocity = {-1.0, 0.0, 2.0};
  const Vec3 f = exchangeUntilAnswered(link, s, 5 * kMs);
  const auto state = bridge.lastState();
  EXPECT_DOUBLE_EQ(state.position[0], 0.010);
  EXPECT_DOUBLE_EQ(state.position[1], -0.030);
  EXPECT_DOUBLE_EQ(state.position[2], 0.020);
  EXPECT_DOUBLE_EQ(state.velocity[0], -0.001);
  EXPECT_DOUBLE_EQ(state.velocity[1], -0.002);
  // Bridge (right 0.1, away 0.2, up 0.3) is OpenHaptics (x 0.1, y up 0.3, z towards the user -0.2).
  EXPECT_DOUBLE_EQ(f[0], 0.1);
  EXPECT_DOUBLE_EQ(f[1], 0.3);
  EXPECT_DOUBLE_EQ(f[2], -0.2);
  EXPECT_TRUE(link.counters().anyOkForce);
}

TEST(BridgeLinkTest, AForceAboveTheDevicesLimitIsScaledDownKeepingItsDirection) {
  FakeBridge bridge({3.0, 0.0, 4.0});  // 5 N
  BridgeLink link(linkTo(bridge, 0.88));
  ASSERT_EQ(link.open(), "");
  const Vec3 f = exchangeUntilAnswered(link, DeviceSample{}, 5 * kMs);
  EXPECT_NEAR(std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]), 0.88, 1e-12);
  EXPECT_NEAR(f[0] / f[1], 3.0 / 4.0, 1e-12);  // bridge x -> device x, bridge z -> device y
  EXPECT_GE(link.counters().forcesClamped, 1u);
}

TEST(BridgeLinkTest, OnlyAnOkForceIsAppliedAndNeverLongerThanTheWatchdog) {
  {
    FakeBridge stopped({1.0, 1.0, 1.0}, BridgeStatus::SafetyStop);
    BridgeLink link(linkTo(stopped, 3.0));
    ASSERT_EQ(link.open(), "");
    const Vec3 f = exchangeUntilAnswered(link, DeviceSample{}, 5 * kMs);
    EXPECT_EQ(f, Vec3{});
    EXPECT_EQ(link.counters().lastStatus, BridgeStatus::SafetyStop);
    EXPECT_FALSE(link.counters().anyOkForce);
  }
  FakeBridge bridge({1.0, 0.0, 0.0});
  BridgeLink link(linkTo(bridge, 3.0));
  ASSERT_EQ(link.open(), "");
  DeviceSample s;
  EXPECT_NE(exchangeUntilAnswered(link, s, 5 * kMs), Vec3{});
  // A device fault zeroes the force at once, whatever the bridge says.
  s.deviceFault = true;
  EXPECT_EQ(link.exchange(s, 5 * kMs), Vec3{});
}

TEST(BridgeLinkTest, AForceHeldPastTheWatchdogTimeIsDropped) {
  FakeBridge bridge({1.0, 0.0, 0.0});
  const BridgeLinkDef def = linkTo(bridge, 3.0);
  BridgeLink link(def);
  ASSERT_EQ(link.open(), "");
  ASSERT_NE(exchangeUntilAnswered(link, DeviceSample{}, 5 * kMs), Vec3{});
  bridge.setAnswering(false);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // answers in flight arrive
  link.exchange(DeviceSample{}, 5 * kMs);                      // ... and are taken, stamped 5 ms
  // Within the bridge's watchdog time the last force holds; past it, zero.
  EXPECT_NE(link.exchange(DeviceSample{}, 5 * kMs + def.forceHoldNs), Vec3{});
  const auto zeroTicks = link.counters().ticksWithoutForce;
  EXPECT_EQ(link.exchange(DeviceSample{}, 5 * kMs + def.forceHoldNs + 1), Vec3{});
  EXPECT_EQ(link.counters().ticksWithoutForce, zeroTicks + 1);
}

TEST(BridgeLinkTest, BadSettingsAreRefusedAtOpen) {
  BridgeLinkDef def;
  def.host = "localhost";
  EXPECT_NE(BridgeLink(def).open().find("not an IPv4 address"), std::string::npos);
  def = BridgeLinkDef{};
  def.maxForce = 0.0;
  EXPECT_NE(BridgeLink(def).open().find("force limit"), std::string::npos);
  def = BridgeLinkDef{};
  def.axes.source = {1, 1, 2};
  EXPECT_NE(BridgeLink(def).open().find("exactly once"), std::string::npos);
}

}  // namespace
}  // namespace hemiroll::sdkclients
