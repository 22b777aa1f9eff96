#include "engine/haptics/devices/MouseDevice.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "engine/haptics/ServoLoop.h"
#include "tests/support/AllocationCounter.h"

namespace hemiroll::haptics {
namespace {

std::atomic<std::int64_t> gNow{0};
std::int64_t fakeNow() { return gNow.load(); }

MouseDeviceDef fakeClockDef() {
  MouseDeviceDef d;
  d.clock = &fakeNow;
  return d;
}

TEST(MouseDeviceTest, RendersNoForceAndSaysSo) {
  MouseDevice m;
  EXPECT_FALSE(m.spec().hasForceOutput);
  EXPECT_TRUE(m.open());
  EXPECT_EQ(m.error(), nullptr);
}

TEST(MouseDeviceTest, FollowsThePointerWithAFilteredVelocity) {
  MouseDevice m(fakeClockDef());
  gNow = 0;
  m.setPointer(Vec3(0.0, 0.0, 0.01));
  m.read(0.0);
  // 0.1 m/s along y for 100 ms, a pointer sample every 1 ms.
  DeviceReading r;
  for (int k = 1; k <= 100; ++k) {
    gNow = k * 1'000'000;
    m.setPointer(Vec3(0.0, 1e-4 * k, 0.01), 1u);
    r = m.read(0.0);
  }
  EXPECT_TRUE(r.fresh);
  EXPECT_EQ(r.position, Vec3(0.0, 0.01, 0.01));
  EXPECT_EQ(r.buttons, 1u);
  // 100 ms = 5 time constants: within e^-5 < 1 % of the speed.
  EXPECT_NEAR(r.velocity.y(), 0.1, 0.001);
}

TEST(MouseDeviceTest, AJumpRestartsTheVelocityFromZero) {
  MouseDevice m(fakeClockDef());
  for (int k = 0; k <= 100; ++k) {
    gNow = k * 1'000'000;
    m.setPointer(Vec3(1e-4 * k, 0.0, 0.0));
    m.read(0.0);
  }
  gNow += 1'000'000;
  m.setPointer(Vec3(-0.05, 0.05, 0.0), 0, true);  // re-entered the window elsewhere
  const DeviceReading r = m.read(0.0);
  EXPECT_EQ(r.position, Vec3(-0.05, 0.05, 0.0));
  EXPECT_EQ(r.velocity, Vec3::Zero());
}

TEST(MouseDeviceTest, BrokenPositionsNeverReachTheLoop) {
  MouseDevice m(fakeClockDef());
  m.setPointer(Vec3(0.01, 0.0, 0.0));
  m.setPointer(Vec3(std::nan(""), 0.0, 0.0));
  const DeviceReading r = m.read(0.0);
  EXPECT_EQ(r.position, Vec3(0.01, 0.0, 0.0));
  EXPECT_TRUE(r.velocity.allFinite());
}

// The real thing on two threads: a UI thread feeding positions while the
// servo loop reads them, and no force reaches the mouse (it has none).
TEST(MouseDeviceTest, AServoLoopDrivenByAUiThreadRendersNothing) {
  MouseDevice m;
  ServoLoopDef def;  // SCHED_FIFO when permitted
  def.safety.engagement.rampTime = 0.05;
  // This test is about the mouse, not timing: a loaded machine without
  // SCHED_FIFO must not trip the loop-overrun watchdog here.
  def.safety.maxTickLateness = 0.5;
  ServoLoop loop(def, m);
  ServoCommand engage;
  engage.kind = ServoCommandKind::Engage;
  m.setPointer(Vec3(0.0, 0.0, 0.04));  // on the mass point at rest
  loop.post(engage);
  loop.start();
  for (int k = 0; k < 200; ++k) {
    m.setPointer(Vec3(0.002 * std::sin(k * 0.05), 0.0, 0.04));
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  loop.stop();
  ServoSnapshot s;
  ASSERT_TRUE(loop.latest(s));
  EXPECT_EQ(s.fault, SafetyFault::None) << safetyFaultName(s.fault);
  EXPECT_EQ(s.engagement, Engagement::Engaged);
  EXPECT_EQ(s.renderedForce, (Triple{0.0, 0.0, 0.0}));
  EXPECT_EQ(m.lastForce(), Vec3::Zero());
}

// The hand feel: the proxy is a simulated hand the pointer pulls and the
// force pushes. With the pointer still and a constant force sent, the
// reading settles F / k from the pointer (k the hand's stated stiffness),
// the same on every run (the fake clock: 1 ms a read).
TEST(MouseDeviceTest, TheHandFeelSettlesOffThePointerByForceOverStiffness) {
  auto run = [] {
    MouseDevice m(mouseHandDef(fakeClockDef()));
    gNow = 0;
    m.setPointer(Vec3(0.0, 0.0, 0.04));
    m.read(0.0);
    m.sendForce(Vec3(0.6, -0.3, 0.0));
    DeviceReading r;
    for (int k = 1; k <= 2000; ++k) {
      gNow = k * 1'000'000;
      r = m.read(0.0);
    }
    return r;
  };
  const DeviceReading r = run();
  const double k = HandSpringDef{}.stiffness;
  EXPECT_NEAR(r.position.x(), 0.6 / k, 1e-12);
  EXPECT_NEAR(r.position.y(), -0.3 / k, 1e-12);
  EXPECT_NEAR(r.position.z(), 0.04, 1e-12);
  EXPECT_NEAR(r.velocity.norm(), 0.0, 1e-9);
  const DeviceReading again = run();
  EXPECT_EQ(r.position, again.position);
  EXPECT_TRUE(MouseDevice(mouseHandDef()).spec().hasForceOutput);  // it renders force: to the hand
}

// A jump of the pointer (the proxy put on the mass point) takes the hand
// there at rest and says so (newPath), instead of a fling; a broken hand is
// refused naming the field (the factory's test makes it by its name).
TEST(MouseDeviceTest, TheHandFeelJumpsWithThePointerAndIsMadeByName) {
  MouseDevice m(mouseHandDef(fakeClockDef()));
  gNow = 0;
  m.setPointer(Vec3(0.0, 0.0, 0.0));
  m.read(0.0);
  gNow = 1'000'000;
  m.setPointer(Vec3(0.03, 0.0, 0.0), 0, true);
  const DeviceReading r = m.read(0.0);
  EXPECT_EQ(r.position, Vec3(0.03, 0.0, 0.0));
  EXPECT_EQ(r.velocity, Vec3::Zero());
  EXPECT_TRUE(r.newPath);

  HandSpringDef bad;
  bad.mass = -1.0;
  try {
    MouseDevice broken(mouseHandDef({}, bad));
    ADD_FAILURE() << "a negative hand mass was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mouse-hand: hand mass"), std::string::npos) << e.what();
  }
}

// Its read() is on the servo thread: no allocation there.
TEST(MouseDeviceTest, TheHandFeelReadsWithoutAllocating) {
  MouseDevice m(mouseHandDef(fakeClockDef()));
  gNow = 0;
  m.setPointer(Vec3(0.0, 0.0, 0.04));
  m.read(0.0);
  ASSERT_TRUE(test::allocationCounterWorks());
  test::AllocationCounter counter(test::AllocationCounter::Threads::Calling);
  for (int k = 1; k <= 100; ++k) {
    gNow = k * 1'000'000;
    m.sendForce(Vec3(0.1, 0.0, 0.0));
    m.read(0.0);
  }
  EXPECT_EQ(counter.count(), 0);
}

}  // namespace
}  // namespace hemiroll::haptics
