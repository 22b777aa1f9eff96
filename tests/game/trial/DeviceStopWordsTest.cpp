// game/trial/DeviceStopWords: every stop in words a lab technician acts on,
// one sentence each, with the figures it was judged against.

#include "game/trial/DeviceStopWords.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>
#include <string>

namespace hemiroll::game {
namespace {

using haptics::SafetyFault;
using ::testing::HasSubstr;

BridgeFacts bridge() {
  BridgeFacts b;
  b.present = true;
  return b;
}

TEST(DeviceStopWords, NoStopHasNoWords) { EXPECT_EQ(deviceStopWords(SafetyFault::None, bridge(), {}), ""); }

TEST(DeviceStopWords, TheBridgesThreeDeviceErrorsAreTold) {
  BridgeFacts stale = bridge();
  stale.stale = true;
  EXPECT_THAT(deviceStopWords(SafetyFault::DeviceError, stale, {}),
              HasSubstr("packets from the device stopped for more than 10 ms (the bridge's watchdog)"));
  BridgeFacts gone = stale;
  gone.clientGone = true;
  gone.silentFor = 0.4;
  EXPECT_THAT(deviceStopWords(SafetyFault::DeviceError, gone, {}),
              HasSubstr("the device's client program has gone (no packet for 400 ms)"));
  BridgeFacts fault = bridge();
  fault.deviceStatus = 7;
  EXPECT_THAT(deviceStopWords(SafetyFault::DeviceError, fault, {}), HasSubstr("the device reported a fault (status 7)"));
}

// The loop's stale-data watchdog can see a silent client before the
// bridge's does; a client that has gone is still named as gone.
TEST(DeviceStopWords, AStaleDeviceWhoseClientHasGoneIsNamedAsGone) {
  BridgeFacts gone = bridge();
  gone.stale = true;
  gone.clientGone = true;
  gone.silentFor = 0.3;
  EXPECT_THAT(deviceStopWords(SafetyFault::StaleDevice, gone, {}),
              HasSubstr("the device's client program has gone (no packet for 300 ms)"));
  BridgeFacts paused = gone;
  paused.clientGone = false;
  EXPECT_THAT(deviceStopWords(SafetyFault::StaleDevice, paused, {}), HasSubstr("stopped updating"));
}

TEST(DeviceStopWords, EveryFaultHasItsOwnSentenceWithItsFigures) {
  StopLimits l;
  l.continuousForce = 0.88;
  l.aboveContinuousLimit = 10.0;
  l.maxTickLateness = 0.02;
  l.staleLimit = 0.01;
  l.maxDeviceSpeed = 2.0;
  EXPECT_THAT(deviceStopWords(SafetyFault::StaleDevice, bridge(), l), HasSubstr("stopped updating for more than 10 ms"));
  EXPECT_THAT(deviceStopWords(SafetyFault::LoopOverrun, bridge(), l), HasSubstr("held up for more than 20 ms"));
  EXPECT_THAT(deviceStopWords(SafetyFault::VelocityGuard, bridge(), l), HasSubstr("faster than 2 m/s"));
  EXPECT_THAT(deviceStopWords(SafetyFault::PositionJump, bridge(), l), HasSubstr("position jumped faster than 2 m/s"));
  EXPECT_THAT(deviceStopWords(SafetyFault::OutsideWorkspace, bridge(), l), HasSubstr("outside the device's workspace"));
  EXPECT_THAT(deviceStopWords(SafetyFault::ForceSaturated, bridge(), l),
              HasSubstr("continuous rating of 0.88 N for more than 10 s"));
  std::set<std::string> sentences;
  for (int f = 1; f <= static_cast<int>(SafetyFault::ForceSaturated); ++f) {
    const std::string words = deviceStopWords(static_cast<SafetyFault>(f), bridge(), l);
    EXPECT_FALSE(words.empty()) << f;
    EXPECT_EQ(words.find(". "), std::string::npos) << "one sentence: " << words;
    sentences.insert(words);
  }
  EXPECT_EQ(sentences.size(), static_cast<std::size_t>(SafetyFault::ForceSaturated)) << "each stop its own words";
}

TEST(DeviceStopWords, PacketCountsAreSpelledOut) {
  haptics::UdpBridgeCounters c;
  c.accepted = 9876;
  c.lost = 3;
  c.outOfOrder = 1;
  c.late = 2;
  EXPECT_EQ(packetCountWords(c), "9876 device states received, 3 lost, 1 out of order, 2 late, 0 malformed");
}

}  // namespace
}  // namespace hemiroll::game
