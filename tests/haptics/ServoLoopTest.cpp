#include "engine/haptics/ServoLoop.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <thread>

#include "engine/haptics/devices/ScriptedDevice.h"
#include "tests/support/AllocationCounter.h"


namespace hemiroll::haptics {
namespace {

constexpr double kRadius = 0.04;  // the default hemisphere: mass point at rest sits at (0, 0, R)
constexpr double kPi = 3.141592653589793;

// The proxy circles 5 mm around the mass point's rest position (the paper's
// small in-face motions), starting exactly on it so that it engages at once.
DeviceReading circling(double t) {
  const double w = 2.0 * kPi, r = 0.005;
  DeviceReading d;
  d.position = Vec3(r * std::sin(w * t), r * (1.0 - std::cos(w * t)), kRadius);
  d.velocity = Vec3(r * w * std::cos(w * t), r * w * std::sin(w * t), 0.0);
  return d;
}

ServoLoopDef quickDef() {
  ServoLoopDef def;
  def.safety.engagement.rampTime = 0.1;
  def.requestRealtime = false;
  return def;
}

ServoCommand command(ServoCommandKind kind) {
  ServoCommand c;
  c.kind = kind;
  return c;
}

struct EngagedRun {
  physics::ForceDrivenState state;
  ServoSnapshot snapshot;
};

EngagedRun engagedRun(long ticks) {
  ScriptedDevice device(circling);
  ServoLoop loop(quickDef(), device);
  EXPECT_TRUE(loop.post(command(ServoCommandKind::Engage)));
  loop.runHeadless(ticks);
  EngagedRun run{loop.state(), {}};
  EXPECT_TRUE(loop.latest(run.snapshot));
  return run;
}

TEST(ServoLoopTest, HeadlessRunsAreBitIdentical) {
  const EngagedRun a = engagedRun(2000), b = engagedRun(2000);
  EXPECT_EQ(std::memcmp(a.state.data(), b.state.data(), sizeof(double) * 12), 0);
  EXPECT_EQ(std::memcmp(&a.snapshot.renderedForce, &b.snapshot.renderedForce, sizeof(Triple)), 0);
  // And the run did something: engaged, moved, rendered a force.
  EXPECT_EQ(a.snapshot.engagement, Engagement::Engaged);
  EXPECT_EQ(a.snapshot.fault, SafetyFault::None) << safetyFaultName(a.snapshot.fault);
  EXPECT_GT(std::hypot(a.state[0], a.state[1]), 1e-4);
  EXPECT_GT(std::hypot(a.snapshot.renderedForce[0], a.snapshot.renderedForce[1]), 1e-3);
  EXPECT_EQ(a.snapshot.tick, 2000u);
  EXPECT_NEAR(a.snapshot.time, 2.0, 1e-9);  // 2000 sums of 1 ms
}

TEST(ServoLoopTest, TheTickDoesNotAllocate) {
  ScriptedDevice device(circling);
  ServoLoop loop(quickDef(), device);
  loop.post(command(ServoCommandKind::Engage));
  loop.runHeadless(10);
  // The counter itself works (else the check below would pass vacuously).
  ASSERT_TRUE(test::allocationCounterWorks());
  test::AllocationCounter counter;
  ServoCommand gains = command(ServoCommandKind::SetCoupling);
  gains.coupling.method = physics::ForceMethod::M1;
  loop.post(gains);
  loop.runHeadless(1000);  // engaged, ramping, coupled, a command applied
  EXPECT_EQ(counter.count(), 0);
  EXPECT_EQ(loop.safety().engagement().state(), Engagement::Engaged);
}

// Recording into the rings allocates nothing either, also when a ring is
// full and rows are dropped (the rings are never drained here).
TEST(ServoLoopTest, RecordingFromTheTickDoesNotAllocate) {
  auto rows = std::make_unique<RecordRing>();
  auto inputs = std::make_unique<InputRing>();
  ScriptedDevice device(circling);
  ServoLoopDef def = quickDef();
  def.recordRing = rows.get();
  def.recordEvery = 1;
  def.inputRing = inputs.get();
  ServoLoop loop(def, device);
  loop.post(command(ServoCommandKind::Engage));
  loop.runHeadless(10);
  ASSERT_TRUE(test::allocationCounterWorks());
  const long ticks = static_cast<long>(RecordRing::capacity()) + 500;  // overflows the row ring
  test::AllocationCounter counter;
  loop.runHeadless(ticks);
  EXPECT_EQ(counter.count(), 0);
  EXPECT_EQ(loop.recordDropped(), static_cast<std::uint64_t>(ticks + 10) - RecordRing::capacity());
  EXPECT_EQ(loop.inputDropped(), 0u);  // 8192 inputs of room
}

// Rows come every recordEvery-th tick and carry the snapshot's values; the
// inputs come every tick, numbered by the tick that read them.
TEST(ServoLoopTest, RecordsEveryNthTickAndEveryInput) {
  auto rows = std::make_unique<RecordRing>();
  auto inputs = std::make_unique<InputRing>();
  ScriptedDevice device(circling);
  ServoLoopDef def = quickDef();
  def.recordRing = rows.get();
  def.recordEvery = 10;
  def.inputRing = inputs.get();
  ServoLoop loop(def, device);
  loop.post(command(ServoCommandKind::Engage));
  loop.runHeadless(95);
  ServoSnapshot last;
  ASSERT_TRUE(loop.latest(last));
  RecordRow row;
  std::uint64_t expected = 10;
  while (rows->pop(row)) {
    EXPECT_EQ(row.tick, expected);
    EXPECT_NEAR(row.time, 0.001 * static_cast<double>(expected), 1e-12);  // sums of 1 ms
    expected += 10;
  }
  EXPECT_EQ(expected, 100u);  // rows at ticks 10..90
  EXPECT_EQ(loop.recordDropped(), 0u);
  TickInput in;
  std::uint64_t tick = 0;
  while (inputs->pop(in)) {
    EXPECT_EQ(in.tick, ++tick);
    const DeviceReading expectedReading = circling(0.001 * static_cast<double>(tick - 1));  // read at the tick's start
    // 1e-15 m: the loop's time is a sum of 1 ms steps, a few ulps from (k - 1) ms.
    EXPECT_NEAR(in.position[0], expectedReading.position.x(), 1e-15);
  }
  EXPECT_EQ(tick, 95u);
  // A row holds what the snapshot of its tick held.
  loop.runHeadless(5);
  ASSERT_TRUE(loop.latest(last));
  ASSERT_TRUE(rows->pop(row));
  EXPECT_EQ(row.tick, last.tick);
  EXPECT_EQ(std::memcmp(row.state.data(), last.state.data(), sizeof row.state), 0);
  EXPECT_EQ(std::memcmp(row.renderedForce.data(), last.renderedForce.data(), sizeof row.renderedForce), 0);
  EXPECT_EQ(row.engagement, last.engagement);
  ServoLoopDef bad = quickDef();
  bad.recordEvery = 0;
  EXPECT_THROW(ServoLoop(bad, device), std::invalid_argument);
}

// In a normal engaged run the model never gains more than the hand's work
// (the estimate stays at or below zero, 0 exactly at engagement), for every
// method: the energy watchdog raises no false alarm.
TEST(ServoLoopTest, EnergyWatchdogIsQuietInANormalRun) {
  for (const auto method : {physics::ForceMethod::M1, physics::ForceMethod::M2, physics::ForceMethod::M3}) {
    ScriptedDevice device(circling);
    ServoLoopDef def = quickDef();
    def.coupling.method = method;
    ServoLoop loop(def, device);
    loop.post(command(ServoCommandKind::Engage));
    double most = -1.0;
    ServoSnapshot s;
    for (int i = 0; i < 3000; ++i) {
      loop.tick();
      ASSERT_TRUE(loop.latest(s));
      most = std::max(most, s.injectedEnergy);
    }
    EXPECT_LE(most, 1e-9) << physics::forceMethodName(method);  // 1e-9 J: rounding of sums of ~1e-4 J terms
    EXPECT_EQ(s.fault, SafetyFault::None);
  }
}

// A device whose position jumps while it reports no velocity (a glitch):
// the model gains energy the hand never supplied, and the watchdog trips.
TEST(ServoLoopTest, EnergyWatchdogTripsOnEnergyFromNowhere) {
  ScriptedDevice device([](double t) {
    DeviceReading d;
    d.position = Vec3(t < 0.3 ? 0.0 : 0.02, 0.0, kRadius);  // velocity stays zero
    return d;
  });
  ServoLoopDef def = quickDef();
  def.safety.maxInjectedEnergy = 0.01;  // [J]; the 2 cm jump stores 0.05 J in the 250 N/m spring
  def.safety.maxForceRate = 1e6;
  def.safety.maxDeviceSpeed = 1e6;
  ServoLoop loop(def, device);
  loop.post(command(ServoCommandKind::Engage));
  loop.runHeadless(1000);
  EXPECT_EQ(loop.safety().fault(), SafetyFault::EnergyInjection);
  EXPECT_EQ(device.lastForce(), Vec3::Zero());
}

TEST(ServoLoopTest, NoInteractionUntilTheProxyReachesTheMassPoint) {
  // The proxy waits 2 cm away for 0.2 s, then moves onto the mass point.
  ScriptedDevice device([](double t) {
    DeviceReading d;
    d.position = Vec3(t < 0.2 ? 0.02 : 0.0, 0.0, kRadius);
    return d;
  });
  ServoLoop loop(quickDef(), device);
  loop.post(command(ServoCommandKind::Engage));
  loop.runHeadless(150);
  ServoSnapshot s;
  ASSERT_TRUE(loop.latest(s));
  EXPECT_EQ(s.engagement, Engagement::Armed);
  EXPECT_NEAR(s.proxyDistance, 0.02, 1e-12);
  EXPECT_EQ(device.lastForce(), Vec3::Zero());
  EXPECT_EQ(loop.state(), physics::ForceDrivenState::Zero());  // the model was not pulled
  loop.runHeadless(100);
  ASSERT_TRUE(loop.latest(s));
  EXPECT_EQ(s.engagement, Engagement::Engaged);
}

TEST(ServoLoopTest, DisengageRampsTheForceOut) {
  ScriptedDevice device(circling);
  ServoLoop loop(quickDef(), device);
  loop.post(command(ServoCommandKind::Engage));
  loop.runHeadless(500);
  loop.post(command(ServoCommandKind::Disengage));
  ServoSnapshot s;
  loop.runHeadless(1);
  ASSERT_TRUE(loop.latest(s));
  EXPECT_EQ(s.engagement, Engagement::RampingOut);
  EXPECT_GT(s.rampScale, 0.9);
  loop.runHeadless(110);  // rampTime 0.1 s
  ASSERT_TRUE(loop.latest(s));
  EXPECT_EQ(s.engagement, Engagement::Disengaged);
  EXPECT_EQ(device.lastForce(), Vec3::Zero());
}

// A device that stops delivering, reports an error, or a hemisphere that
// spins away: the force is zero in the tick the watchdog fires and the
// physics stops.
TEST(ServoLoopTest, StalledDeviceZeroesTheForceAndPauses) {
  ScriptedDevice device(circling);
  ServoLoop loop(quickDef(), device);
  loop.post(command(ServoCommandKind::Engage));
  loop.runHeadless(500);
  ASSERT_NE(device.lastForce(), Vec3::Zero());
  device.stallFrom(loop.time());
  loop.runHeadless(11);  // 10 ms staleLimit: by the 11th stale tick it has fired
  ServoSnapshot s;
  ASSERT_TRUE(loop.latest(s));
  EXPECT_EQ(s.fault, SafetyFault::StaleDevice);
  EXPECT_TRUE(s.paused);
  EXPECT_EQ(device.lastForce(), Vec3::Zero());
  const double frozen = loop.time();
  loop.runHeadless(10);
  EXPECT_EQ(loop.time(), frozen);
}

TEST(ServoLoopTest, DeviceErrorZeroesTheForceInTheSameTick) {
  ScriptedDevice device(circling);
  ServoLoop loop(quickDef(), device);
  loop.post(command(ServoCommandKind::Engage));
  loop.runHeadless(500);
  ASSERT_NE(device.lastForce(), Vec3::Zero());
  device.failWith("cable pulled");
  loop.runHeadless(1);
  EXPECT_EQ(device.lastForce(), Vec3::Zero());
  EXPECT_EQ(loop.safety().fault(), SafetyFault::DeviceError);
}

TEST(ServoLoopTest, RunawayRotationZeroesTheForce) {
  ServoLoopDef def = quickDef();
  def.initialState[physics::force_slot::w_z] = 150.0;  // below the 200 rad/s bound
  ScriptedDevice device(circling);
  ServoLoop loop(def, device);
  loop.post(command(ServoCommandKind::Engage));
  loop.runHeadless(5);
  EXPECT_FALSE(loop.safety().faulted());
  ServoCommand spin = command(ServoCommandKind::ResetState);
  spin.state[physics::force_slot::w_z] = 250.0;
  spin.time = loop.time();
  loop.post(spin);
  loop.runHeadless(1);
  EXPECT_EQ(loop.safety().fault(), SafetyFault::RunawayRotation);
  EXPECT_EQ(device.lastForce(), Vec3::Zero());
}

TEST(ServoLoopTest, PauseAndResumeByCommand) {
  ScriptedDevice device(circling);
  ServoLoop loop(quickDef(), device);
  loop.post(command(ServoCommandKind::Engage));
  loop.runHeadless(300);
  loop.post(command(ServoCommandKind::Pause));
  loop.runHeadless(1);
  EXPECT_EQ(device.lastForce(), Vec3::Zero());
  const double t = loop.time();
  loop.runHeadless(5);
  EXPECT_EQ(loop.time(), t);
  loop.post(command(ServoCommandKind::Resume));
  loop.runHeadless(5);
  EXPECT_GT(loop.time(), t);
}

TEST(ServoLoopTest, RejectsCouplingsTheDeviceCannotRender) {
  ScriptedDevice device(circling);
  ServoLoop loop(quickDef(), device);
  ServoCommand c = command(ServoCommandKind::SetCoupling);
  c.coupling.stiffness = 800.0;  // M3 with alpha 2: 1600 N/m normal > the spec's 1000
  EXPECT_FALSE(loop.post(c));
  c.coupling.stiffness = -1.0;
  EXPECT_FALSE(loop.post(c));
  c.coupling.stiffness = 100.0;
  EXPECT_TRUE(loop.post(c));
}

// A clock whose waits return late by a scripted amount at chosen wake-ups.
class FakeClock final : public ServoClock {
 public:
  std::map<long, std::int64_t> delays;  // wake-up index -> extra lateness [ns]
  std::int64_t now() override { return now_; }
  void waitUntil(std::int64_t deadline) override {
    now_ = std::max(now_, deadline);
    const auto it = delays.find(waits_++);
    if (it != delays.end()) now_ += it->second;
  }

 private:
  std::int64_t now_ = 0;
  long waits_ = 0;
};

constexpr std::int64_t kPeriodNs = 1'000'000;

TEST(ServoLoopCatchUpTest, OnTimeWakeupsRunOneTickEach) {
  ScriptedDevice device(circling);
  ServoLoop loop(quickDef(), device);
  FakeClock clock;
  loop.runPaced(clock, 100);
  EXPECT_EQ(loop.ticks(), 100u);
  EXPECT_EQ(loop.missedTicks(), 0u);
  EXPECT_EQ(clock.now(), 100 * kPeriodNs);
  EXPECT_EQ(loop.lateness().max(), 0.0);
  EXPECT_EQ(loop.wakePeriod().count(), 99u);
}

TEST(ServoLoopCatchUpTest, ASmallStallIsCaughtUpOnTheSameGrid) {
  ScriptedDevice device(circling);
  ServoLoop loop(quickDef(), device);  // maxCatchUpTicks = 3
  FakeClock clock;
  clock.delays[10] = 2 * kPeriodNs + kPeriodNs / 2;  // 2.5 periods late: 3 deadlines due
  loop.runPaced(clock, 20);
  EXPECT_EQ(loop.ticks(), 22u);
  EXPECT_EQ(loop.missedTicks(), 0u);
  EXPECT_EQ(clock.now(), 22 * kPeriodNs);  // the last wake-up is still on the original grid
  EXPECT_NEAR(loop.time(), 0.022, 1e-12);
  EXPECT_DOUBLE_EQ(loop.lateness().max(), 2.5e-3);
  const LoopTimingSummary t = loop.timingSummary();
  EXPECT_EQ(t.ticks, 22u);
  EXPECT_EQ(t.wakeups, 20u);
  EXPECT_DOUBLE_EQ(t.latenessMax, 2.5e-3);
  EXPECT_DOUBLE_EQ(t.periodMax, 3.5e-3);  // wake-up 10 came 2.5 ms late
  // Most wake-ups are exactly 1 ms apart: the bin [1000, 1001) us, reported by its upper edge.
  EXPECT_DOUBLE_EQ(t.periodP50, 1.001e-3);
}

TEST(ServoLoopCatchUpTest, ALongStallSkipsTicksAndReanchors) {
  ScriptedDevice device(circling);
  ServoLoopDef def = quickDef();
  def.safety.maxTickLateness = 10.0;  // the pacing alone; the overrun watchdog is tested below
  ServoLoop loop(def, device);
  FakeClock clock;
  clock.delays[10] = 10 * kPeriodNs + kPeriodNs / 2;  // 11 deadlines due: 3 run, 8 skipped
  clock.delays[15] = 1'000'000'000;                   // a whole second: still only 3 ticks
  loop.runPaced(clock, 20);
  EXPECT_EQ(loop.ticks(), 18u + 3u + 3u);
  EXPECT_EQ(loop.missedTicks(), 8u + 998u);
  // Simulation time advanced by the ticks run only: no jump, no backlog.
  EXPECT_NEAR(loop.time(), 0.024, 1e-12);
  // Re-anchored at now + period after each stall: wake-up 10 at 11 + 10.5 ms,
  // wake-ups 11..15 one period apart (the last one 1 s late), then 16..19.
  EXPECT_EQ(clock.now(), (11 * kPeriodNs + 10 * kPeriodNs + kPeriodNs / 2) + 5 * kPeriodNs + 1'000'000'000 +
                             4 * kPeriodNs);
}

TEST(ServoLoopCatchUpTest, AStallBeyondTheOverrunLimitZeroesTheForce) {
  ScriptedDevice device(circling);
  ServoLoop loop(quickDef(), device);  // maxTickLateness 20 ms
  loop.post(command(ServoCommandKind::Engage));
  FakeClock clock;
  clock.delays[300] = 15 * kPeriodNs;  // a hiccup below the limit: caught up, no fault
  clock.delays[400] = 30 * kPeriodNs;
  loop.runPaced(clock, 400);
  EXPECT_FALSE(loop.safety().faulted());
  ASSERT_NE(device.lastForce(), Vec3::Zero());
  loop.runPaced(clock, 1);
  EXPECT_EQ(loop.safety().fault(), SafetyFault::LoopOverrun);
  EXPECT_EQ(device.lastForce(), Vec3::Zero());
}

// Stops that fit the device (issue 27). A device without force output (the
// mouse) has no force to hold while a tick is late: its loop is not
// stopped, it catches up (up to maxCatchUpTicks: PlaySession gives it 100)
// and slows its clock beyond, and stalls() counts what it rode out. The
// same stall on a device that renders force stops it, as before.
TEST(ServoLoopCatchUpTest, AForcelessDeviceRidesAStallOutAForceDeviceStops) {
  ServoLoopDef def = quickDef();  // maxTickLateness 20 ms
  def.maxCatchUpTicks = 100;
  DeviceSpec mouse{"mouse", 0.0, 1000.0, 0.1, false};
  ScriptedDevice forceless(circling, mouse);
  ServoLoop loop(def, forceless);
  loop.post(command(ServoCommandKind::Engage));
  FakeClock clock;
  clock.delays[100] = 30 * kPeriodNs;   // 30 ms: caught up in full
  clock.delays[200] = 300 * kPeriodNs;  // 300 ms: 100 ticks run, 200 not made up
  loop.runPaced(clock, 300);
  EXPECT_FALSE(loop.safety().faulted()) << safetyFaultName(loop.safety().fault());
  EXPECT_EQ(loop.stalls(), 2u);
  EXPECT_EQ(loop.missedTicks(), 201u);              // 301 deadlines were due at the second, 100 ran
  EXPECT_EQ(loop.ticks(), 300u + 30u + 99u);        // every wake-up, the first stall's 30, the second's 99 more
  EXPECT_NEAR(loop.time(), 0.429, 1e-9);            // the clock slowed by the 201 ticks, no jump
  EXPECT_EQ(loop.timingSummary().stalls, 2u);
  ServoSnapshot s;
  ASSERT_TRUE(loop.latest(s));
  EXPECT_EQ(s.stalls, 2u);
  EXPECT_EQ(s.fault, SafetyFault::None);

  // The same 30 ms stall with a desk device that renders force.
  ScriptedDevice forceful(circling);
  ServoLoop stopped(def, forceful);
  stopped.post(command(ServoCommandKind::Engage));
  FakeClock again;
  again.delays[100] = 30 * kPeriodNs;
  stopped.runPaced(again, 150);
  EXPECT_EQ(stopped.safety().fault(), SafetyFault::LoopOverrun);
  EXPECT_EQ(stopped.stalls(), 1u);
  EXPECT_EQ(forceful.lastForce(), Vec3::Zero());
}

// The real thread on the real clock for ~0.3 s. Asserts only what a loaded
// 2-core machine cannot break: it ticks, the statistics agree with each
// other, the snapshot reaches another thread, stop() leaves a zero force.
TEST(ServoLoopRealtimeTest, TicksAndKeepsConsistentStatistics) {
  ScriptedDevice device(circling);
  ServoLoopDef def = quickDef();
  def.requestRealtime = true;  // a note, never an error, when not permitted
  ServoLoop loop(def, device);
  ASSERT_TRUE(loop.post(command(ServoCommandKind::Engage)));
  loop.start();
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
  ServoSnapshot s;
  std::uint64_t seen = 0;
  while (std::chrono::steady_clock::now() < until) {
    if (loop.latest(s)) seen = std::max(seen, s.tick);
    std::this_thread::yield();
  }
  loop.stop();
  EXPECT_GT(loop.ticks(), 0u);
  EXPECT_GT(seen, 0u);
  EXPECT_LE(seen, loop.ticks());
  EXPECT_EQ(loop.lateness().count(), loop.ticks());
  EXPECT_EQ(loop.wakePeriod().count(), loop.wakeups() - 1);
  EXPECT_LE(loop.wakeups(), loop.ticks());
  EXPECT_LE(loop.lateness().quantile(0.5), loop.lateness().quantile(0.999));
  EXPECT_LE(loop.lateness().quantile(0.999), loop.lateness().max());
  EXPECT_NE(loop.realtime().status, RealtimeStatus::NotRequested);
  EXPECT_NE(loop.realtime().note, nullptr);
  EXPECT_EQ(device.lastForce(), Vec3::Zero());
  ASSERT_TRUE(loop.latest(s));
  EXPECT_EQ(s.tick, loop.ticks());
}

}  // namespace
}  // namespace hemiroll::haptics

namespace hemiroll::haptics {
namespace {

// The planner's channel carries the same snapshots as the renderer's, from
// the first tick after a planner first asked (before, the tick skips it).
TEST(ServoLoopTest, ThePlannersChannelStartsWhenAPlannerAsks) {
  ScriptedDevice device(circling);
  ServoLoop loop(quickDef(), device);
  loop.runHeadless(5);
  ServoSnapshot forPlanner, forRenderer;
  EXPECT_FALSE(loop.latestForPlanner(forPlanner));  // asked now: nothing written yet
  loop.runHeadless(3);
  ASSERT_TRUE(loop.latestForPlanner(forPlanner));
  ASSERT_TRUE(loop.latest(forRenderer));
  EXPECT_EQ(forPlanner.tick, 8u);
  EXPECT_EQ(forPlanner.tick, forRenderer.tick);
  EXPECT_EQ(forPlanner.state, forRenderer.state);
}

}  // namespace
}  // namespace hemiroll::haptics
