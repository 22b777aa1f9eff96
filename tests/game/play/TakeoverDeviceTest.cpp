// game/play/TakeoverDevice: the autopilot's hand holds until the handover,
// the player's device feels nothing before it, and the switch of readings is
// no motion: the position-jump guard does not stop a force device whose hand
// is centimetres from where the autopilot left the proxy.
#include "game/play/TakeoverDevice.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/haptics/ServoLoop.h"

namespace hemiroll::game {
namespace {

constexpr double kRadius = 0.04;  // the default hemisphere: the mass point rests at (0, 0, R)

// The player's force device, with the hand 5 cm from the mass point; it
// remembers the last force it was sent.
class FarHand final : public haptics::HapticDevice {
 public:
  const haptics::DeviceSpec& spec() const override { return spec_; }
  bool open() override { return true; }
  void close() override {}
  haptics::DeviceReading read(double) override {
    haptics::DeviceReading r;
    r.position = haptics::Vec3(0.05, 0.0, kRadius);
    return r;
  }
  void sendForce(const haptics::Vec3& f) override { lastForce = f; }
  const char* error() const override { return nullptr; }
  haptics::Vec3 lastForce = haptics::Vec3::Zero();

 private:
  haptics::DeviceSpec spec_;  // a desk device: force output, 3 N
};

TEST(TakeoverDeviceTest, TheHandoverIsNoJumpAndThePlayerFeltNothingBefore) {
  haptics::ServoLoopDef def;
  def.requestRealtime = false;
  def.safety.engagement.rampTime = 0.01;
  FarHand hand;
  HandoffBotDevice autopilot(hand.spec(), def.mapping);
  TakeoverDevice device(autopilot, hand);
  haptics::ServoLoop loop(def, device);
  haptics::ServoCommand c;
  c.kind = haptics::ServoCommandKind::Engage;
  ASSERT_TRUE(loop.post(c));
  // The autopilot holds 3 mm beside the mass point: a coupling force, all of it its own.
  for (int tick = 0; tick < 200; ++tick) {
    autopilot.publish(loop.time(), haptics::Vec3(0.003, 0.0, kRadius), haptics::Vec3::Zero());
    loop.tick();
  }
  haptics::ServoSnapshot s;
  ASSERT_TRUE(loop.latest(s));
  EXPECT_EQ(s.engagement, haptics::Engagement::Engaged);
  EXPECT_GT(std::hypot(s.renderedForce[0], s.renderedForce[1], s.renderedForce[2]), 0.1);
  EXPECT_EQ(hand.lastForce, haptics::Vec3::Zero()) << "the player felt the autopilot's force";
  // It lets go; once disengaged the device is handed over (PlaySession's order).
  c.kind = haptics::ServoCommandKind::Disengage;
  ASSERT_TRUE(loop.post(c));
  for (int tick = 0; tick < 100 && s.engagement != haptics::Engagement::Disengaged; ++tick) {
    autopilot.publish(loop.time(), haptics::Vec3(0.003, 0.0, kRadius), haptics::Vec3::Zero());
    loop.tick();
    loop.latest(s);
  }
  ASSERT_EQ(s.engagement, haptics::Engagement::Disengaged);
  device.handToPlayer();
  for (int tick = 0; tick < 50; ++tick) loop.tick();
  ASSERT_TRUE(loop.latest(s));
  // 47 mm in one tick is far beyond the velocity guard's reach, but it is a
  // change of device, not a motion: no fault.
  EXPECT_EQ(s.fault, haptics::SafetyFault::None) << haptics::safetyFaultName(s.fault);
  EXPECT_NEAR(s.proxyPosition[0], 0.05, 1e-15);
  EXPECT_EQ(hand.lastForce, haptics::Vec3::Zero());  // disengaged: nothing yet
}

// Without the newPath mark the same switch is what the guard exists for.
TEST(TakeoverDeviceTest, AJumpWithoutANewPathStillTripsTheGuard) {
  haptics::SafetyDef def;
  haptics::ForceSafety safety(def, haptics::DeviceSpec{});
  haptics::SafetyInputs in;
  in.devicePosition = haptics::Vec3::Zero();
  safety.update(in);
  in.devicePosition = haptics::Vec3(0.047, 0.0, 0.0);
  safety.update(in);
  EXPECT_EQ(safety.fault(), haptics::SafetyFault::PositionJump);
  haptics::ForceSafety restarted(def, haptics::DeviceSpec{});
  in.devicePosition = haptics::Vec3::Zero();
  restarted.update(in);
  in.devicePosition = haptics::Vec3(0.047, 0.0, 0.0);
  in.newDevicePath = true;
  restarted.update(in);
  EXPECT_EQ(restarted.fault(), haptics::SafetyFault::None);
}

}  // namespace
}  // namespace hemiroll::game
