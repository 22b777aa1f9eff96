// The servo tick's rules, checked for every device the factory makes: read(),
// error() and sendForce() allocate nothing (house rule for the 1 kHz tick),
// and what they report is finite.

#include <SDL.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "engine/haptics/devices/sdl/DeviceFactory.h"
#include "tests/support/AllocationCounter.h"


namespace hemiroll::haptics {
namespace {

// 1000 ticks' worth of servo-side calls; the allocations they made.
long allocationsOverTicks(HapticDevice& device, const std::function<void()>& beforeEachTick = {}) {
  device.read(0.0);  // first call outside the count: lazy set-up is allowed at open
  // The calling thread's only: the devices' own threads (the bridge's
  // receiver, the joystick's SDL thread) are not charged to the servo side.
  test::AllocationCounter counter(test::AllocationCounter::Threads::Calling);
  counter.pause();
  for (int k = 1; k <= 1000; ++k) {
    if (beforeEachTick) beforeEachTick();
    counter.resume();
    const DeviceReading r = device.read(k * 0.001);
    const char* e = device.error();
    device.sendForce(Vec3(0.1, -0.2, 0.05));
    counter.pause();
    EXPECT_TRUE(r.position.allFinite() && r.velocity.allFinite());
    (void)e;
  }
  return counter.count();
}

TEST(DeviceTickTest, TheCounterCounts) { EXPECT_TRUE(test::allocationCounterWorks()); }

TEST(DeviceTickTest, ScriptedSimulatedHandAndMouseAllocateNothingPerTick) {
  const DeviceFactory f;
  for (const char* name : {"scripted", "simulated-hand", "mouse"}) {
    DeviceChoice c = f.makeAndOpen(name);
    ASSERT_TRUE(c.device) << c.error;
    EXPECT_EQ(allocationsOverTicks(*c.device), 0) << name;
  }
  // The mouse while its UI thread feeds it (here: this thread between ticks).
  DeviceChoice c = f.makeAndOpen("mouse");
  auto& mouse = static_cast<MouseDevice&>(*c.device);
  int k = 0;
  EXPECT_EQ(allocationsOverTicks(mouse, [&] { mouse.setPointer(Vec3(1e-4 * ++k, 0.0, 0.0)); }), 0);
}

TEST(DeviceTickTest, UdpBridgeAllocatesNothingPerTickWithAClientSending) {
  DeviceOptions o;
  o.udp.port = 0;
  DeviceChoice c = DeviceFactory().makeAndOpen("udp", o);
  ASSERT_TRUE(c.device) << c.error;
  auto& bridge = static_cast<UdpBridgeDevice&>(*c.device);
  UdpSocket client;
  ASSERT_EQ(client.bind({0x7F000001u, 0}), "");
  std::uint32_t sequence = 0;
  auto sendState = [&] {
    udp::StateMessage m;
    m.sequence = ++sequence;
    m.position = {0.01, 0.0, 0.0};
    std::uint8_t b[udp::kStateSize];
    client.send(b, udp::encodeState(m, b), {0x7F000001u, bridge.port()});
  };
  sendState();
  ASSERT_TRUE(bridge.waitForClient(1.0));
  EXPECT_EQ(allocationsOverTicks(bridge, sendState), 0);
  EXPECT_GT(bridge.counters().forcesSent, 900u);  // the sends really happened
}

TEST(DeviceTickTest, SdlJoystickAllocatesNothingPerTick) {
  setenv("SDL_VIDEODRIVER", "dummy", 1);
  ASSERT_EQ(SDL_InitSubSystem(SDL_INIT_JOYSTICK), 0) << SDL_GetError();
  const int index = SDL_JoystickAttachVirtual(SDL_JOYSTICK_TYPE_GAMECONTROLLER, 2, 2, 0);
  ASSERT_GE(index, 0) << SDL_GetError();
  DeviceOptions o;
  o.joystick.index = index;
  o.joystick.requireForceFeedback = false;  // SDL's virtual sticks have no SDL_Haptic
  DeviceChoice c = DeviceFactory().makeAndOpen("joystick", o);
  ASSERT_TRUE(c.device) << c.error;
  EXPECT_EQ(allocationsOverTicks(*c.device), 0);
  c.device->close();
  SDL_JoystickDetachVirtual(index);
  SDL_QuitSubSystem(SDL_INIT_JOYSTICK);
}

}  // namespace
}  // namespace hemiroll::haptics
