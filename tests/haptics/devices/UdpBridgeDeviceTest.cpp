#include "engine/haptics/devices/UdpBridgeDevice.h"

#include "engine/haptics/ForceSafety.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

namespace hemiroll::haptics {
namespace {

// The watchdog runs on this clock in these tests, so that 9.9 ms and 10.1 ms
// are exact and no test sleeps for them.
std::atomic<std::int64_t> gFakeNow{1'000'000'000};
std::int64_t fakeNow() { return gFakeNow.load(); }

UdpBridgeDef testDef() {
  UdpBridgeDef def;
  def.port = 0;  // any free port
  def.clock = &fakeNow;
  def.spec.maxForce = 2.0;
  return def;
}

// A stand-in for a client: a socket of its own on loopback.
class FakeClient {
 public:
  explicit FakeClient(std::uint16_t bridgePort) {
    EXPECT_EQ(socket_.bind({0x7F000001u, 0}), "");
    bridge_ = {0x7F000001u, bridgePort};
  }
  void sendBytes(const std::uint8_t* data, std::size_t n) { ASSERT_TRUE(socket_.send(data, n, bridge_)); }
  void sendState(const udp::StateMessage& m) {
    std::uint8_t b[udp::kStateSize];
    sendBytes(b, udp::encodeState(m, b));
  }
  // The next force datagram, waiting up to 1 s (generous: the receiver
  // thread only has to wake on a loaded 2-core machine).
  bool receiveForce(udp::ForceMessage& out) {
    std::uint8_t b[udp::kMaxDatagram];
    UdpEndpoint from;
    const long n = socket_.receive(b, sizeof b, from, 1'000'000'000);
    return n > 0 && udp::decodeForce(b, static_cast<std::size_t>(n), out) == udp::DecodeError::None;
  }

 private:
  UdpSocket socket_;
  UdpEndpoint bridge_;
};

udp::StateMessage state(std::uint32_t sequence, double x = 0.01) {
  udp::StateMessage m;
  m.sequence = sequence;
  m.timestampNs = 1000 + sequence;
  m.position = {x, 0.02, 0.03};
  m.velocity = {0.1, 0.0, -0.1};
  m.buttons = 3;
  return m;
}

// Waits (up to 1 s) until the receiver has taken n datagrams in all.
bool waitReceived(const UdpBridgeDevice& d, std::uint64_t n) {
  for (int i = 0; i < 1000 && d.counters().received < n; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return d.counters().received >= n;
}

TEST(UdpBridgeDeviceTest, RefusesNonLoopbackUnlessAskedAndNamesTheAddress) {
  UdpBridgeDef def = testDef();
  def.bindAddress = "0.0.0.0";
  UdpBridgeDevice open(def);
  EXPECT_FALSE(open.open());
  ASSERT_NE(open.error(), nullptr);
  EXPECT_NE(std::string(open.error()).find("refusing to bind 0.0.0.0"), std::string::npos) << open.error();

  def.allowNonLoopback = true;
  UdpBridgeDevice allowed(def);
  EXPECT_TRUE(allowed.open()) << allowed.error();
}

TEST(UdpBridgeDeviceTest, BadAddressAndBusyPortGiveSentences) {
  UdpBridgeDef def = testDef();
  def.bindAddress = "localhost";
  UdpBridgeDevice named(def);
  EXPECT_FALSE(named.open());
  EXPECT_NE(std::string(named.error()).find("'localhost' is not an IPv4 address"), std::string::npos);

  UdpBridgeDevice first(testDef());
  ASSERT_TRUE(first.open());
  def = testDef();
  def.port = first.port();
  UdpBridgeDevice second(def);
  EXPECT_FALSE(second.open());
  EXPECT_NE(std::string(second.error()).find("cannot bind UDP 127.0.0.1:" + std::to_string(first.port())),
            std::string::npos)
      << second.error();
}

TEST(UdpBridgeDeviceTest, NoClientYetIsAnErrorAndNotFresh) {
  UdpBridgeDevice d(testDef());
  ASSERT_TRUE(d.open());
  const DeviceReading r = d.read(0.0);
  EXPECT_FALSE(r.fresh);
  ASSERT_NE(d.error(), nullptr);
  EXPECT_NE(std::string(d.error()).find("no client"), std::string::npos);
}

TEST(UdpBridgeDeviceTest, StateInForceOutAnsweringThatState) {
  UdpBridgeDevice d(testDef());
  ASSERT_TRUE(d.open());
  FakeClient client(d.port());
  client.sendState(state(7));
  ASSERT_TRUE(waitReceived(d, 1));

  const DeviceReading r = d.read(0.0);
  EXPECT_EQ(d.error(), nullptr);
  EXPECT_TRUE(r.fresh);
  EXPECT_EQ(r.position, Vec3(0.01, 0.02, 0.03));
  EXPECT_EQ(r.velocity, Vec3(0.1, 0.0, -0.1));
  EXPECT_EQ(r.buttons, 3u);
  EXPECT_FALSE(d.read(0.001).fresh);  // same sample again

  d.sendForce(Vec3(0.5, -0.25, 0.0));
  udp::ForceMessage f;
  ASSERT_TRUE(client.receiveForce(f));
  EXPECT_EQ(f.answers, 7u);
  EXPECT_EQ(f.echoTimestampNs, 1007u);
  EXPECT_EQ(f.status, udp::BridgeStatus::Ok);
  EXPECT_EQ(f.force[0], 0.5);
  EXPECT_EQ(f.force[1], -0.25);

  // A force above the spec (2 N) leaves the bridge at 2 N whatever the caller did.
  d.sendForce(Vec3(30.0, 40.0, 0.0));
  ASSERT_TRUE(client.receiveForce(f));
  EXPECT_LE(Vec3(f.force[0], f.force[1], f.force[2]).norm(), 2.0);
  EXPECT_NEAR(f.force[0], 1.2, 1e-12);  // direction kept: (3, 4) / 5 * 2
  EXPECT_GT(f.sequence, 0u);
}

TEST(UdpBridgeDeviceTest, MalformedDatagramsAreCountedAndDropped) {
  UdpBridgeDevice d(testDef());
  ASSERT_TRUE(d.open());
  FakeClient client(d.port());
  client.sendState(state(1, 0.01));
  std::uint8_t b[udp::kMaxDatagram + 40] = {};
  udp::encodeState(state(2, 0.05), b);
  b[0] = 'X';  // bad magic
  client.sendBytes(b, udp::kStateSize);
  client.sendBytes(b, 5);  // too short
  udp::encodeState(state(3, 0.05), b);
  client.sendBytes(b, udp::kStateSize - 1);  // size mismatch
  client.sendBytes(b, sizeof b);             // oversized datagram
  b[4] = 9;                                  // unknown version
  client.sendBytes(b, udp::kStateSize);
  ASSERT_TRUE(waitReceived(d, 6));
  const UdpBridgeCounters c = d.counters();
  EXPECT_EQ(c.malformed, 5u);
  EXPECT_EQ(c.accepted, 1u);
  EXPECT_EQ(d.lastDecodeError(), udp::DecodeError::BadVersion);
  EXPECT_EQ(d.read(0.0).position.x(), 0.01);  // only the good state got through
}

// Received + out of order + lost is what the client sent: a state that
// arrives after a later one is out of order (and dropped), not also lost.
TEST(UdpBridgeDeviceTest, OutOfOrderAndDuplicatesAreDroppedGapsCountedAsLost) {
  UdpBridgeDevice d(testDef());
  ASSERT_TRUE(d.open());
  FakeClient client(d.port());
  client.sendState(state(10, 0.010));
  client.sendState(state(13, 0.013));  // 11 and 12 missing
  client.sendState(state(12, 0.012));  // late: not lost after all
  client.sendState(state(13, 0.013));  // duplicate
  client.sendState(state(12, 0.012));  // duplicate of a late one: no second un-losing
  ASSERT_TRUE(waitReceived(d, 5));
  const UdpBridgeCounters c = d.counters();
  EXPECT_EQ(c.accepted, 2u);
  EXPECT_EQ(c.outOfOrder, 3u);
  EXPECT_EQ(c.lost, 1u);  // 11 never came
  EXPECT_EQ(d.read(0.0).position.x(), 0.013);
  // A gap wider than the window stays lost whatever arrives later.
  client.sendState(state(200, 0.2));
  client.sendState(state(14, 0.014));  // 186 behind: out of the 63-state window
  ASSERT_TRUE(waitReceived(d, 7));
  EXPECT_EQ(d.counters().lost, 1u + 186u);
}

// A good state more than latePacket (2 ms) after the previous one is late;
// silentFor and the device's fault status are what a stop's words need.
TEST(UdpBridgeDeviceTest, LateStatesSilenceAndTheDevicesFaultAreKept) {
  UdpBridgeDevice d(testDef());
  ASSERT_TRUE(d.open());
  EXPECT_LT(d.silentFor(), 0.0);  // nothing yet
  FakeClient client(d.port());
  client.sendState(state(1));
  ASSERT_TRUE(waitReceived(d, 1));
  gFakeNow.fetch_add(1'900'000);  // 1.9 ms: on time
  client.sendState(state(2));
  ASSERT_TRUE(waitReceived(d, 2));
  EXPECT_EQ(d.counters().late, 0u);
  gFakeNow.fetch_add(2'100'000);  // 2.1 ms: late
  udp::StateMessage faulty = state(3);
  faulty.deviceStatus = 5;
  client.sendState(faulty);
  ASSERT_TRUE(waitReceived(d, 3));
  EXPECT_EQ(d.counters().late, 1u);
  EXPECT_EQ(d.lastDeviceFault(), 5);
  EXPECT_EQ(d.silentFor(), 0.0);  // the fake clock has not moved since
  gFakeNow.fetch_add(250'000'000);
  EXPECT_DOUBLE_EQ(d.silentFor(), 0.25);
}

TEST(UdpBridgeDeviceTest, WatchdogTripsAfterTenMillisecondsAndZeroesTheForce) {
  UdpBridgeDevice d(testDef());
  ASSERT_TRUE(d.open());
  FakeClient client(d.port());
  client.sendState(state(1));
  ASSERT_TRUE(waitReceived(d, 1));
  const std::int64_t arrival = gFakeNow.load();

  gFakeNow.store(arrival + 9'900'000);  // 9.9 ms of silence: still healthy
  d.read(0.0);
  EXPECT_EQ(d.error(), nullptr);
  gFakeNow.store(arrival + 10'100'000);  // 10.1 ms: the watchdog
  d.read(0.0);
  ASSERT_NE(d.error(), nullptr);
  EXPECT_NE(std::string(d.error()).find("watchdog"), std::string::npos);

  d.sendForce(Vec3(1.0, 0.0, 0.0));  // even if a caller still asked for force
  udp::ForceMessage f;
  ASSERT_TRUE(client.receiveForce(f));
  EXPECT_EQ(f.status, udp::BridgeStatus::Stale);
  EXPECT_EQ(f.force, (std::array<double, 3>{0.0, 0.0, 0.0}));

  client.sendState(state(2));  // the client is back: healthy again (the loop's fault stays latched)
  ASSERT_TRUE(waitReceived(d, 2));
  EXPECT_TRUE(d.read(0.0).fresh);
  EXPECT_EQ(d.error(), nullptr);
}

TEST(UdpBridgeDeviceTest, ASecondSenderIsIgnoredWhileTheClientIsAlive) {
  UdpBridgeDevice d(testDef());
  ASSERT_TRUE(d.open());
  FakeClient client(d.port()), intruder(d.port());
  client.sendState(state(1, 0.01));
  ASSERT_TRUE(waitReceived(d, 1));
  intruder.sendState(state(1, 0.09));
  ASSERT_TRUE(waitReceived(d, 2));
  EXPECT_EQ(d.counters().otherSender, 1u);
  EXPECT_EQ(d.read(0.0).position.x(), 0.01);

  gFakeNow.fetch_add(20'000'000);  // the client went silent: a new one may take over
  intruder.sendState(state(1, 0.09));
  ASSERT_TRUE(waitReceived(d, 3));
  EXPECT_EQ(d.read(0.0).position.x(), 0.09);
  EXPECT_EQ(d.counters().clientChanges, 2u);
}

TEST(UdpBridgeDeviceTest, ADeviceFaultFromTheClientIsAnError) {
  UdpBridgeDevice d(testDef());
  ASSERT_TRUE(d.open());
  FakeClient client(d.port());
  udp::StateMessage m = state(1);
  m.deviceStatus = 3;
  client.sendState(m);
  ASSERT_TRUE(waitReceived(d, 1));
  d.read(0.0);
  ASSERT_NE(d.error(), nullptr);
  EXPECT_NE(std::string(d.error()).find("fault of its device"), std::string::npos);
  // The client is told why its force is zero (it heard status 0; issue 19).
  d.sendForce(Vec3(1.0, 0.0, 0.0));
  udp::ForceMessage f;
  ASSERT_TRUE(client.receiveForce(f));
  EXPECT_EQ(f.status, udp::BridgeStatus::DeviceFault);
  EXPECT_EQ(f.force, (std::array<double, 3>{0.0, 0.0, 0.0}));
}

// A safety stop of hemiroll's (a watchdog of the servo loop: here the
// velocity guard) was sent as status 0, so a client could not tell it from a
// commanded zero force (issue 33). It is status SafetyStop, naming the fault;
// once cleared, the status is ok again.
TEST(UdpBridgeDeviceTest, ASafetyStopIsToldWithItsFault) {
  UdpBridgeDevice d(testDef());
  ASSERT_TRUE(d.open());
  FakeClient client(d.port());
  client.sendState(state(1));
  ASSERT_TRUE(waitReceived(d, 1));
  d.read(0.0);
  d.safetyState(static_cast<std::uint8_t>(SafetyFault::VelocityGuard));
  d.sendForce(Vec3::Zero());
  udp::ForceMessage f;
  ASSERT_TRUE(client.receiveForce(f));
  EXPECT_EQ(f.status, udp::BridgeStatus::SafetyStop);
  EXPECT_EQ(f.safetyFault, static_cast<std::uint8_t>(SafetyFault::VelocityGuard));
  EXPECT_STREQ(safetyFaultName(static_cast<SafetyFault>(f.safetyFault)), safetyFaultName(SafetyFault::VelocityGuard));
  d.safetyState(0);
  d.sendForce(Vec3(0.5, 0.0, 0.0));
  ASSERT_TRUE(client.receiveForce(f));
  EXPECT_EQ(f.status, udp::BridgeStatus::Ok);
  EXPECT_EQ(f.safetyFault, 0);
  EXPECT_EQ(f.force[0], 0.5);
}

TEST(UdpBridgeDeviceTest, CloseTellsTheClient) {
  UdpBridgeDevice d(testDef());
  ASSERT_TRUE(d.open());
  FakeClient client(d.port());
  client.sendState(state(5));
  ASSERT_TRUE(waitReceived(d, 1));
  d.read(0.0);
  d.close();
  udp::ForceMessage f;
  ASSERT_TRUE(client.receiveForce(f));
  EXPECT_EQ(f.status, udp::BridgeStatus::Closing);
  EXPECT_EQ(f.force, (std::array<double, 3>{0.0, 0.0, 0.0}));
  EXPECT_NE(d.error(), nullptr);
}

}  // namespace
}  // namespace hemiroll::haptics
