// tools/sdkclients/ClientRun with each SDK's driver against a fake of the
// SDK calls it makes (FakeHd, FakeDhd, FakeFalcon) and a fake bridge on
// loopback: the order of start-up and shut-down, the units and axes on the
// wire and back, and that no device pushes before the bridge says ok.
// Not run on hardware: docs/UDP_BRIDGE.md says how a lab checks a client.

#include "tools/sdkclients/ClientRun.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/tools/sdkclients/FakeBridge.h"
#include "tests/tools/sdkclients/FakeSdk.h"
#include "tools/sdkclients/falcon/FalconDriver.h"
#include "tools/sdkclients/omega/OmegaDriver.h"
#include "tools/sdkclients/touch/TouchDriver.h"

namespace hemiroll::sdkclients {
namespace {

using haptics::udp::BridgeStatus;
using test::FakeBridge;
using test::FakeSdk;

ClientRunDef runFor(const FakeBridge& bridge, double seconds, double maxForce = 3.0) {
  ClientRunDef def;
  def.link.port = bridge.port();
  def.link.maxForce = maxForce;
  def.duration = seconds;
  def.pollNs = 2'000'000;
  return def;
}

void expectInOrder(FakeSdk& sdk, const std::vector<std::string>& names) {
  for (std::size_t i = 0; i + 1 < names.size(); ++i) {
    EXPECT_LT(sdk.at(names[i]), sdk.at(names[i + 1])) << names[i] << " before " << names[i + 1];
    EXPECT_LT(sdk.at(names[i + 1]), sdk.calls.size()) << names[i + 1] << " was called";
  }
}

TEST(ClientRunTest, TouchStartsForcesOffAndTakesDownInReverse) {
  FakeSdk& sdk = test::fakeHd();
  sdk.reset();
  FakeBridge bridge({0.1, 0.2, 0.3});
  TouchDriver driver;
  std::atomic<bool> stop{false};
  const ClientRunResult r = runDeviceClient(driver, runFor(bridge, 0.3), stop);
  ASSERT_EQ(r.error, "");
  EXPECT_TRUE(r.forcesWereEnabled);
  expectInOrder(sdk, {"hdInitDevice", "hdScheduleAsynchronous", "hdStartScheduler", "hdEnable(HD_FORCE_OUTPUT)",
                      "hdDisable(HD_FORCE_OUTPUT)", "hdStopScheduler", "hdUnschedule", "hdDisableDevice"});
  EXPECT_EQ(sdk.pushedWhileOff.load(), 0);
  // The pose in millimetres, OpenHaptics' axes, reached the bridge in metres, its axes.
  const auto state = bridge.lastState();
  EXPECT_DOUBLE_EQ(state.position[0], 0.010);
  EXPECT_DOUBLE_EQ(state.position[1], -0.030);
  EXPECT_DOUBLE_EQ(state.position[2], 0.020);
  EXPECT_DOUBLE_EQ(state.velocity[2], 0.002);
  // The SDK's own continuous force (0.88 N in the fake), read once the device is open, is the limit.
  EXPECT_DOUBLE_EQ(r.forceLimit, 0.88);
  EXPECT_GT(r.counters.forcesReceived, 100u);
}

TEST(ClientRunTest, TouchNeverPushesAboveItsContinuousForce) {
  FakeSdk& sdk = test::fakeHd();
  sdk.reset();
  FakeBridge bridge({0.0, 0.0, 5.0});  // 5 N up, far above a Touch's 0.88 N
  TouchDriver driver;
  std::atomic<bool> stop{false};
  ASSERT_EQ(runDeviceClient(driver, runFor(bridge, 0.2), stop).error, "");
  // Through the whole run nothing above the limit was written, and the
  // device did push, at the limit.
  EXPECT_LE(sdk.largestForce, 0.88 + 1e-12);
  EXPECT_GT(sdk.largestForce, 0.88 - 1e-12);
  EXPECT_EQ(sdk.pushedWhileOff.load(), 0);
}

TEST(ClientRunTest, ADeviceThatWillNotOpenIsNamedAndNothingElseIsCalled) {
  FakeSdk& sdk = test::fakeHd();
  sdk.reset();
  sdk.failOpen = true;
  FakeBridge bridge({0.0, 0.0, 0.0});
  TouchDriver driver;
  std::atomic<bool> stop{false};
  const ClientRunResult r = runDeviceClient(driver, runFor(bridge, 0.2), stop);
  EXPECT_NE(r.error.find("hdInitDevice failed: HD error 257"), std::string::npos) << r.error;
  EXPECT_EQ(sdk.at("hdStartScheduler"), sdk.calls.size());
  EXPECT_EQ(bridge.statesReceived(), 0u);
}

TEST(ClientRunTest, OmegaMapsItsAxesAndSwitchesForcesInOrder) {
  FakeSdk& sdk = test::fakeDhd();
  sdk.reset();
  FakeBridge bridge({0.1, 0.2, 0.3});
  OmegaDriver driver;
  std::atomic<bool> stop{false};
  const ClientRunResult r = runDeviceClient(driver, runFor(bridge, 0.3), stop);
  ASSERT_EQ(r.error, "");
  expectInOrder(sdk, {"dhdOpen", "dhdEnableForce(DHD_ON)", "dhdEnableForce(DHD_OFF)", "dhdClose"});
  EXPECT_EQ(sdk.pushedWhileOff.load(), 0);
  const auto state = bridge.lastState();  // DHD: x towards the user, y right, z up
  EXPECT_DOUBLE_EQ(state.position[0], 0.02);
  EXPECT_DOUBLE_EQ(state.position[1], -0.01);
  EXPECT_DOUBLE_EQ(state.position[2], 0.03);
  sdk.reset();
  sdk.failOpen = true;
  OmegaDriver closed;
  const ClientRunResult none = runDeviceClient(closed, runFor(bridge, 0.1), stop);
  EXPECT_NE(none.error.find("dhdOpen failed: no device found (fake)"), std::string::npos) << none.error;
}

TEST(ClientRunTest, FalconIsHomedCentredAndSilentUntilTheBridgeSaysOk) {
  FakeSdk& sdk = test::fakeFalcon();
  sdk.reset();
  {
    FakeBridge stopped({1.0, 1.0, 1.0}, BridgeStatus::SafetyStop);
    FalconDriver driver(FalconDriverDef{});
    std::atomic<bool> stop{false};
    const ClientRunResult r = runDeviceClient(driver, runFor(stopped, 0.2), stop);
    ASSERT_EQ(r.error, "");
    EXPECT_FALSE(r.forcesWereEnabled);
    EXPECT_EQ(sdk.pushedWhileOff.load(), 0);  // libnifalcon has no switch: every force written was zero
    expectInOrder(sdk, {"setFalconFirmware", "open", "setHomingMode", "close"});
    // 0.03 m towards the user from the centre is 0.03 m towards the user on the bridge.
    const auto state = stopped.lastState();
    EXPECT_NEAR(state.position[1], -0.03, 1e-12);
    EXPECT_NEAR(state.position[0], 0.0, 1e-12);
  }
  sdk.reset();
  FakeBridge bridge({0.1, 0.2, 0.3});
  FalconDriver driver(FalconDriverDef{});
  std::atomic<bool> stop{false};
  const ClientRunResult r = runDeviceClient(driver, runFor(bridge, 0.3), stop);
  ASSERT_EQ(r.error, "");
  EXPECT_TRUE(r.forcesWereEnabled);
  EXPECT_GT(sdk.pushedWhileOff.load(), 0);  // now it pushed: the fake cannot tell "on" from the driver's zero
}

}  // namespace
}  // namespace hemiroll::sdkclients
