// game/trial/DeviceTrial: a trial at a device behind the UDP bridge, end to
// end over loopback with the reference client's simulated device on a
// thread of this process: the recorded force never exceeds the profile,
// every stop is named in words (one test per fault the bridge and the
// profile add), and injected packet faults are counted.

#include "game/trial/DeviceTrial.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <thread>

#include "engine/haptics/RecordRow.h"
#include "engine/script/DeviceProfileLoader.h"
#include "engine/script/LevelLoader.h"
#include "game/trial/DeviceProfiles.h"
#include "tools/hapticclient/HapticClient.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

const std::string kSource = HEMIROLL_SOURCE_DIR;

// Out of reach: the trial runs to its 1.5 s limit unless a stop ends it.
constexpr const char* kLevel = R"lua(
return {
  name = "device field",
  params = { R = 0.04, m_s = 1.0, m_p = 0.2, g = 9.81 },
  task = { targets = { u_ca = { value = {0.5, 0.5}, tol = 0.004 } }, time_limit = 1.5 },
}
)lua";

task::DeviceProfileDef profile(const std::string& source) {
  return script::DeviceProfileLoader().loadSource(source, "test_device.lua");
}

// A small desk device whose clamp and continuous rating a circling hand reaches.
std::string smallDevice(double peak, double continuous, double limit) {
  return "return { model = 'Small Device', peak_force_N = " + std::to_string(peak) +
         ", continuous_force_N = " + std::to_string(continuous) + ", above_continuous_limit_s = " +
         std::to_string(limit) +
         ", max_stiffness_N_per_m = 2000, workspace_width_m = 0.2, workspace_depth_m = 0.2,"
         " workspace_height_m = 0.2, update_rate_Hz = 1000 }";
}

// The hand starts on the mass point (the coupling engages) and circles.
hapticclient::ClientOptions clientNear(double duration = 3.0) {
  hapticclient::ClientOptions o;
  o.duration = duration;
  o.centre = {0.0, 0.0, 0.04};
  o.circleRadius = 0.01;
  o.circleFrequency = 1.0;
  o.handleMass = 0.05;
  o.friction = 0.02;
  o.resolution = 0.000055;
  o.realtimePriority = 70;
  return o;
}

struct Played {
  TrialResult result;
  haptics::SafetyFault stop = haptics::SafetyFault::None;
  std::string words;
  haptics::UdpBridgeCounters counters;
  double largestForce = 0.0;  // [N] over every tick
  hapticclient::ClientSummary client;
};

// These tests are about what each stop is called; the watchdogs' timing is
// UdpBridgeDeviceTest's and ForceSafetyTest's. Under ctest -j2 on two
// loaded cores a client can be starved past 10 ms (PlaySessionTest measured
// a fault at 0.16 s), so the bridge's watchdog gets 100 ms here and the
// loop's overrun 0.5 s. The loop's stale-data watchdog, the second line
// behind the bridge's, gets 300 ms: it counts ticks, and after a stall the
// loop's catch-up ticks find no fresh state, so at the bridge's 100 ms it
// raced the bridge to name a silence (DeviceTrial and DeviceStopWords name
// a gone client either way; these tests pin the bridge's own words).
Played play(const task::DeviceProfileDef& device, hapticclient::ClientOptions client) {
  script::LoadedLevel level = script::LevelLoader().loadSource(kLevel, "level.lua");
  DeviceTrialDef def;
  def.bridge.port = 0;  // any free port
  def.bridge.watchdog = 0.1;
  def.bridge.spec = deviceSpecOf(device);
  haptics::SafetyDef tolerant;
  tolerant.staleLimit = 0.3;
  tolerant.maxTickLateness = 0.5;
  def.safety = safetyOf(device, tolerant);
  def.clientTimeout = 5.0;
  DeviceTrial trial(level, def);
  auto ring = std::make_unique<haptics::RecordRing>();
  trial.rig().record({ring.get(), 1});
  client.port = trial.port();
  Played out;
  std::atomic<bool> stopClient{false};
  std::thread clientThread([&] { out.client = hapticclient::runClient(client, stopClient); });
  out.result = trial.run();
  stopClient = true;
  clientThread.join();
  out.stop = trial.stop();
  out.words = trial.stopWords();
  out.counters = trial.counters();
  haptics::RecordRow row;
  while (ring->pop(row))
    out.largestForce = std::max(out.largestForce, haptics::Vec3(row.renderedForce[0], row.renderedForce[1],
                                                                row.renderedForce[2]).norm());
  return out;
}

// results.csv's device columns have one set of names for every trial.
TEST(DeviceTrial, TheDeviceColumnsAreTheSameForEveryTrial) {
  haptics::UdpBridgeCounters c;
  c.accepted = 1000;
  c.lost = 2;
  c.outOfOrder = 1;
  c.late = 3;
  const record::Fields udp = deviceResultFields("udp", "the words", &c);
  const record::Fields bot = deviceResultFields(nullptr);
  ASSERT_EQ(udp.size(), bot.size());
  for (std::size_t i = 0; i < udp.size(); ++i) EXPECT_EQ(udp[i].first, bot[i].first);
  EXPECT_EQ(udp, (record::Fields{{"device", "udp"}, {"stop", "the words"}, {"packets_received", "1000"},
                                 {"packets_lost", "2"}, {"packets_out_of_order", "1"}, {"packets_late", "3"},
                                 {"packets_malformed", "0"}}));
  EXPECT_EQ(bot[0].second, "bot");
  for (std::size_t i = 1; i < bot.size(); ++i) EXPECT_EQ(bot[i].second, "") << bot[i].first;
  EXPECT_EQ(deviceResultFields("mouse", "", nullptr)[0].second, "mouse");
}

TEST(DeviceTrial, NoClientIsAFailureThatSaysWhatToStart) {
  script::LoadedLevel level = script::LevelLoader().loadSource(kLevel, "level.lua");
  DeviceTrialDef def;
  def.bridge.port = 0;
  def.clientTimeout = 0.2;
  DeviceTrial trial(level, def);
  const TrialResult r = trial.run();
  EXPECT_EQ(r.outcome, task::TrialOutcome::Failure);
  EXPECT_EQ(r.reason, "no device: no state from a client on 127.0.0.1:" + std::to_string(trial.port()) +
                          " within 0.2 s; start the device's client (docs/UDP_BRIDGE.md) before the trial");
  EXPECT_EQ(trial.stop(), haptics::SafetyFault::None);
}

TEST(DeviceTrial, TheRecordedForceNeverExceedsTheProfilesPeak) {
  constexpr double kPeak = 0.3;  // [N]
  const Played p = play(profile(smallDevice(kPeak, kPeak, 100.0)), clientNear());
  EXPECT_EQ(p.stop, haptics::SafetyFault::None) << p.words << " / " << p.result.reason;
  EXPECT_EQ(p.result.reason, "time limit reached") << p.result.reason;
  EXPECT_LE(p.largestForce, kPeak);
  EXPECT_GT(p.largestForce, 0.99 * kPeak) << "the clamp was never reached: the test could not see it fail";
  EXPECT_LE(p.client.maxForce, kPeak);
}

TEST(DeviceTrial, APauseOfThePacketsIsTheWatchdog) {
  hapticclient::ClientOptions c = clientNear();
  c.pauseAt = 0.3;
  c.pauseFor = 0.15;  // past the 100 ms watchdog; back well before the client counts as gone
  const Played p = play(profile(smallDevice(3.0, 3.0, 100.0)), c);
  EXPECT_EQ(p.stop, haptics::SafetyFault::DeviceError);
  EXPECT_THAT(p.words, HasSubstr("packets from the device stopped for more than 100 ms"));
  EXPECT_THAT(p.result.reason, HasSubstr("safety stop: packets from the device stopped"));
}

TEST(DeviceTrial, AClientThatLeavesIsGone) {
  hapticclient::ClientOptions c = clientNear();
  c.exitAt = 0.3;
  const Played p = play(profile(smallDevice(3.0, 3.0, 100.0)), c);
  EXPECT_TRUE(p.client.exited);
  EXPECT_EQ(p.stop, haptics::SafetyFault::DeviceError);
  EXPECT_THAT(p.words, HasSubstr("the device's client program has gone"));
}

TEST(DeviceTrial, TheDevicesFaultStatusIsNamed) {
  hapticclient::ClientOptions c = clientNear();
  c.faultAt = 0.3;
  const Played p = play(profile(smallDevice(3.0, 3.0, 100.0)), c);
  EXPECT_EQ(p.stop, haptics::SafetyFault::DeviceError);
  EXPECT_THAT(p.words, HasSubstr("the device reported a fault (status 1)"));
}

TEST(DeviceTrial, AHandleOutsideTheWorkspaceIsNamed) {
  hapticclient::ClientOptions c = clientNear();
  c.centre = {0.0, 0.2, 0.04};  // 0.1 m beyond the Touch's 35 mm half-depth
  const Played p = play(script::DeviceProfileLoader().loadFile(kSource + "/devices/touch.lua"), c);
  EXPECT_EQ(p.stop, haptics::SafetyFault::OutsideWorkspace);
  EXPECT_THAT(p.words, HasSubstr("outside the device's workspace"));
}

TEST(DeviceTrial, AForceHeldAboveTheContinuousRatingIsNamed) {
  const Played p = play(profile(smallDevice(3.0, 0.05, 0.2)), clientNear());
  EXPECT_EQ(p.stop, haptics::SafetyFault::ForceSaturated) << p.result.reason;
  EXPECT_THAT(p.words, HasSubstr("above the device's continuous rating of 0.05 N for more than 0.2 s"));
}

TEST(DeviceTrial, LostAndReorderedPacketsAreCounted) {
  hapticclient::ClientOptions c = clientNear();
  c.loss = 0.02;
  c.reorder = 0.02;
  c.seed = 7;
  const Played p = play(profile(smallDevice(3.0, 3.0, 100.0)), c);
  EXPECT_EQ(p.stop, haptics::SafetyFault::None) << p.words;
  // The client's own books: what it dropped and held back.
  EXPECT_GT(p.client.statesDropped, 0u);
  EXPECT_GT(p.client.statesReordered, 0u);
  // Each state held back arrives after the next one: out of order at the
  // bridge, so those counts are at most the client's. Each state dropped
  // while the bridge was listening is a gap it counts; drops after its
  // loop stopped (the client runs on until it is told to stop, longer on
  // a loaded machine) it never sees, so only those within the answered
  // span bound its count from below.
  EXPECT_GT(p.counters.outOfOrder, 0u);
  EXPECT_LE(p.counters.outOfOrder, p.client.statesReordered);
  EXPECT_GT(p.client.statesDroppedWhileAnswered, 0u);
  EXPECT_LE(p.client.statesDroppedWhileAnswered, p.client.statesDropped);
  EXPECT_GE(p.counters.lost, p.client.statesDroppedWhileAnswered);
}

}  // namespace
}  // namespace hemiroll::game
