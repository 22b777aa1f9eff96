// tools/hapticclient/SimulatedDevice: the simulated device's limits and
// feel (clamp, friction, quantisation), its network (loss, reorder,
// jitter from a seed), and the step watch's latency.

#include "tools/hapticclient/SimulatedDevice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace hemiroll::hapticclient {
namespace {

using haptics::Vec3;

haptics::SimulatedHandDevice::IntentFunction still() {
  return [](double) { return haptics::SimulatedHandDevice::Intent{}; };
}

DeviceModelDef passive() {
  DeviceModelDef d;
  d.hand.stiffness = 0.0;
  d.hand.damping = 0.0;
  d.hand.mass = 0.1;
  return d;
}

TEST(SimulatedDevice, TheMotorsClampAtThePeakForce) {
  DeviceModelDef d = passive();
  d.peakForce = 3.3;
  DeviceModel device(still(), d);
  device.setForce(Vec3(10.0, 0.0, 0.0));
  EXPECT_NEAR(device.rendered().norm(), 3.3, 1e-12);
  device.setForce(Vec3(0.0, 1.0, 0.0));
  EXPECT_EQ(device.rendered(), Vec3(0.0, 1.0, 0.0));
}

// A passive handle pushed for 0.1 s then let go: friction stops it after
// v^2 / (2 f / m); without friction it coasts on.
struct Coast {
  double speed = 0.0;   // [m/s] when let go
  double travel = 0.0;  // [m] after
};
Coast coast(double friction) {
  DeviceModelDef d = passive();
  d.friction = friction;
  DeviceModel device(still(), d);
  device.setForce(Vec3(1.0, 0.0, 0.0));
  for (int i = 1; i < 100; ++i) device.read(i * 0.001);
  device.setForce(Vec3::Zero());
  const haptics::DeviceReading let = device.read(0.1);
  double x = let.position.x();
  for (int i = 101; i <= 1000; ++i) x = device.read(i * 0.001).position.x();
  return {let.velocity.x(), x - let.position.x()};
}

TEST(SimulatedDevice, FrictionStopsACoastingHandle) {
  const Coast free = coast(0.0), braked = coast(0.5);
  EXPECT_NEAR(free.travel, free.speed * 0.9, 1e-9);  // no friction: uniform motion
  const double decel = 0.5 / 0.1;                   // f / m [m/s^2]
  // 1 mm: the explicit steps' error over ~100 steps of 1 ms; and it stays
  // stopped (the friction brakes, never pushes back).
  EXPECT_NEAR(braked.travel, braked.speed * braked.speed / (2.0 * decel), 0.001);
  EXPECT_GT(braked.speed, 0.3);
}

TEST(SimulatedDevice, PositionsAreWholeEncoderCounts) {
  DeviceModelDef d = passive();
  d.resolution = 0.001;
  DeviceModel device([](double) {
    haptics::SimulatedHandDevice::Intent i;
    i.position = Vec3(0.01234, -0.00456, 0.0007);
    return i;
  }, d);
  const haptics::DeviceReading r = device.read(0.001);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.position[k] / 0.001, std::round(r.position[k] / 0.001), 1e-9) << k;
  EXPECT_NEAR(r.position.x(), 0.012, 1e-12);
}

OutgoingLink::Datagram numbered(int n) {
  OutgoingLink::Datagram d{};
  d[0] = static_cast<std::uint8_t>(n & 0xff);
  d[1] = static_cast<std::uint8_t>(n >> 8);
  return d;
}
int numberOf(const OutgoingLink::Datagram& d) { return d[0] | (d[1] << 8); }

std::vector<int> sentOver(OutgoingLink& link, int count, std::int64_t periodNs) {
  std::vector<int> sent;
  for (int i = 0; i < count; ++i) {
    const std::int64_t now = i * periodNs;
    link.push(numbered(i), now);
    link.sendDue(now, [&](const OutgoingLink::Datagram& d) { sent.push_back(numberOf(d)); });
  }
  link.sendDue(INT64_MAX, [&](const OutgoingLink::Datagram& d) { sent.push_back(numberOf(d)); });
  return sent;
}

TEST(SimulatedDevice, APerfectLinkSendsEverythingInOrderAtOnce) {
  OutgoingLink link({});
  const std::vector<int> sent = sentOver(link, 200, 1'000'000);
  ASSERT_EQ(sent.size(), 200u);
  for (int i = 0; i < 200; ++i) EXPECT_EQ(sent[static_cast<std::size_t>(i)], i);
}

TEST(SimulatedDevice, LossDropsAboutItsShareAndCountsIt) {
  OutgoingLink link({0.0, 0.1, 0.0, 5});
  const std::vector<int> sent = sentOver(link, 2000, 1'000'000);
  EXPECT_EQ(sent.size() + link.lost(), 2000u);
  // Binomial(2000, 0.1): mean 200, sd 13.4; +-5 sd.
  EXPECT_GT(link.lost(), 133u);
  EXPECT_LT(link.lost(), 267u);
}

TEST(SimulatedDevice, AReorderedStateGoesRightAfterTheNextOne) {
  OutgoingLink link({0.0, 0.0, 0.05, 5});
  const std::vector<int> sent = sentOver(link, 2000, 1'000'000);
  ASSERT_GT(link.reordered(), 0u);
  std::uint64_t swaps = 0;
  for (std::size_t i = 1; i < sent.size(); ++i)
    if (sent[i] < sent[i - 1]) {
      EXPECT_EQ(sent[i] + 1, sent[i - 1]) << "held back by one";
      ++swaps;
    }
  EXPECT_EQ(swaps, link.reordered() - (sent.size() < 2000 ? 1 : 0));
}

TEST(SimulatedDevice, JitterDelaysWithinItsBound) {
  OutgoingLink link({0.0005, 0.0, 0.0, 5});
  link.push(numbered(1), 0);
  const std::int64_t release = link.nextRelease();
  EXPECT_GE(release, 0);
  EXPECT_LE(release, 500'000);
}

TEST(SimulatedDevice, TheStepWatchTimesTheFirstForceThatAnswers) {
  StepWatch watch(0.02);
  watch.forceReceived(9, Vec3(0.1, 0.0, 0.0), 900);
  watch.stepSent(10, 1000);
  watch.forceReceived(9, Vec3(0.5, 0.0, 0.0), 1100);    // answers a state before the step: not it
  watch.forceReceived(10, Vec3(0.11, 0.0, 0.0), 1200);  // too small a change
  watch.forceReceived(11, Vec3(0.2, 0.0, 0.0), 1500);
  ASSERT_EQ(watch.latencies().size(), 1u);
  EXPECT_DOUBLE_EQ(watch.latencies()[0], 500e-9);
}

}  // namespace
}  // namespace hemiroll::hapticclient
