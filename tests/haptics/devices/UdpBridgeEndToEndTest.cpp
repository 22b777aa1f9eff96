// The UDP bridge end to end: the servo loop on its real-time thread, the
// bridge on loopback, and the reference client (hemiroll-haptic-client, a
// spring-mass hand) as a child process.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <thread>

#include "engine/haptics/ServoLoop.h"
#include "engine/haptics/devices/UdpBridgeDevice.h"
#include "tests/support/ChildProcess.h"

namespace hemiroll::haptics {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kRadius = 0.04;        // default hemisphere: the mass point rests at (0, 0, R)
constexpr double kCircle = 0.005;       // the client's hand circles 5 mm ...
constexpr double kMaxForce = 0.05;      // ... against a device limited to 0.05 N, so the clamp works

std::map<std::string, double> parseSummary(const std::string& text) {
  std::map<std::string, double> m;
  std::istringstream in(text);
  std::string key;
  double value = 0.0;
  while (in >> key >> value) m[key] = value;
  return m;
}

ServoCommand command(ServoCommandKind kind) {
  ServoCommand c;
  c.kind = kind;
  return c;
}

// Whether this process may use SCHED_FIFO (asked on a throwaway thread).
bool fifoPermitted() {
  RealtimeStatus status = RealtimeStatus::NotRequested;
  std::thread([&] { status = requestFifoScheduling(1).status; }).join();
  return status == RealtimeStatus::Fifo;
}

TEST(UdpBridgeEndToEndTest, ProxyFollowsTheClientForcesAreClampedAndSilenceZeroesThem) {
  // All three threads (servo loop, bridge receiver, client) ask for
  // SCHED_FIFO: under the normal scheduler a loaded 2-core machine (ctest -j2)
  // starves one of them for over 10 ms now and then (two CPU hogs: 8 failures
  // in 8 runs; with SCHED_FIFO 8 passes), which the watchdogs rightly report
  // as a silent device or a stalled loop. Where SCHED_FIFO is not permitted
  // (a container without CAP_SYS_NICE) they get 100 ms instead, so that the
  // test measures the bridge rather than the machine's load; the 10 ms limit
  // itself is tested exactly, on a fake clock, in UdpBridgeDeviceTest.
  const double watchdog = fifoPermitted() ? 0.010 : 0.100;
  UdpBridgeDef bridgeDef;
  bridgeDef.port = 0;
  bridgeDef.spec.maxForce = kMaxForce;
  bridgeDef.watchdog = watchdog;
  UdpBridgeDevice bridge(bridgeDef);
  ASSERT_TRUE(bridge.open()) << bridge.error();

  test::ChildProcess client(HEMIROLL_HAPTIC_CLIENT,
                            {"--port", std::to_string(bridge.port()), "--duration", "30", "--centre",
                             "0,0," + std::to_string(kRadius), "--circle-radius", std::to_string(kCircle),
                             "--circle-frequency", "1", "--realtime-priority", "70"});
  ASSERT_TRUE(bridge.waitForClient(5.0)) << "the client sent nothing; stderr: " << client.err();

  ServoLoopDef def;
  def.safety.engagement.rampTime = 0.1;
  def.safety.staleLimit = watchdog;
  def.safety.maxTickLateness = std::max(def.safety.maxTickLateness, watchdog);
  ServoLoop loop(def, bridge);
  ASSERT_TRUE(loop.post(command(ServoCommandKind::Engage)));
  loop.start();

  // 1.5 s of play, watched through the snapshots the renderer would read.
  const Vec3 circleCentre(0.0, kCircle, kRadius);
  double minX = 1.0, maxX = -1.0, worstRadiusError = 0.0, maxRendered = 0.0;
  bool clamped = false, engaged = false;
  ServoSnapshot s;
  const auto playEnd = Clock::now() + std::chrono::milliseconds(1500);
  while (Clock::now() < playEnd) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    if (!loop.latest(s)) continue;
    ASSERT_EQ(s.fault, SafetyFault::None) << safetyFaultName(s.fault) << ": " << (bridge.error() ? bridge.error() : "");
    const Vec3 p(s.proxyPosition[0], s.proxyPosition[1], s.proxyPosition[2]);
    minX = std::min(minX, p.x());
    maxX = std::max(maxX, p.x());
    worstRadiusError = std::max(worstRadiusError, std::abs((p - circleCentre).norm() - kCircle));
    maxRendered = std::max(maxRendered, Vec3(s.renderedForce[0], s.renderedForce[1], s.renderedForce[2]).norm());
    clamped = clamped || s.forceClamped;
    engaged = engaged || s.engagement == Engagement::Engaged;
  }
  // The proxy follows the client's hand around its circle: it spans the
  // circle's width, and stays on it to within 1 mm (the hand gives way by
  // at most F/k_h = 0.05 N / 300 N/m = 0.17 mm under the force, the rest is
  // its spring-mass lag at 1 Hz).
  EXPECT_GT(maxX - minX, 1.6 * kCircle);
  EXPECT_LT(worstRadiusError, 0.001);
  EXPECT_TRUE(engaged);
  EXPECT_TRUE(clamped) << "the coupling never asked for more than the device's limit";
  EXPECT_LE(maxRendered, kMaxForce);

  // The client goes silent (SIGTERM: it stops sending and prints its summary).
  client.signal(SIGTERM);
  EXPECT_EQ(client.wait(), 0) << client.err();
  const auto silent = Clock::now();
  bool tripped = false;
  while (Clock::now() - silent < std::chrono::seconds(1)) {
    if (loop.latest(s) && s.fault != SafetyFault::None) {
      tripped = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  const double detectMs = std::chrono::duration<double, std::milli>(Clock::now() - silent).count();
  loop.stop();
  ASSERT_TRUE(tripped);
  EXPECT_EQ(s.fault, SafetyFault::DeviceError) << safetyFaultName(s.fault);
  EXPECT_EQ(s.renderedForce, (Triple{0.0, 0.0, 0.0}));
  EXPECT_TRUE(s.paused);
  ASSERT_NE(bridge.error(), nullptr);
  EXPECT_NE(std::string(bridge.error()).find("watchdog"), std::string::npos) << bridge.error();

  // What crossed the socket, both ways.
  const std::map<std::string, double> summary = parseSummary(client.out());
  const UdpBridgeCounters c = bridge.counters();
  std::cout << "[bridge] states accepted " << c.accepted << ", malformed " << c.malformed << ", out of order "
            << c.outOfOrder << ", lost " << c.lost << ", forces sent " << c.forcesSent << ", send failures "
            << c.sendFailures << "; fault seen " << detectMs << " ms after the client exited\n"
            << "[client]\n" << client.out() << "[scheduling] loop: " << loop.realtime().note
            << "; receiver: " << bridge.receiverRealtime().note << "; watchdog " << watchdog * 1e3 << " ms\n";
  ASSERT_TRUE(summary.count("forces_received")) << client.out() << client.err();
  EXPECT_GT(summary.at("forces_received"), 1000.0);  // ~1.5 s at 1 kHz, plus the time before the loop started
  EXPECT_LE(summary.at("max_force_N"), kMaxForce);
  EXPECT_GT(summary.at("max_force_N"), 0.5 * kMaxForce);
  EXPECT_EQ(c.malformed, 0u);
  // Loopback loses nothing and reorders nothing.
  EXPECT_EQ(c.outOfOrder, 0u);
  EXPECT_EQ(summary.at("forces_out_of_order"), 0.0);
  EXPECT_EQ(summary.at("forces_malformed"), 0.0);
}

}  // namespace
}  // namespace hemiroll::haptics
