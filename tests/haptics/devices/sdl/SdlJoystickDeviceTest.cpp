#include "engine/haptics/devices/sdl/SdlJoystickDevice.h"

#include <SDL.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <thread>

namespace hemiroll::haptics {
namespace {

// SDL's dummy drivers: no window system, no sound, and no joystick unless a
// test attaches a virtual one. The test holds its own reference on the
// joystick subsystem, as the game's main thread would.
class SdlJoystickDeviceTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    setenv("SDL_VIDEODRIVER", "dummy", 1);
    setenv("SDL_AUDIODRIVER", "dummy", 1);
  }
  void SetUp() override { ASSERT_EQ(SDL_InitSubSystem(SDL_INIT_JOYSTICK), 0) << SDL_GetError(); }
  void TearDown() override { SDL_QuitSubSystem(SDL_INIT_JOYSTICK); }

  static std::string openError(const SdlJoystickDef& def) {
    SdlJoystickDevice d(def);
    EXPECT_FALSE(d.open());
    return d.error() != nullptr ? d.error() : "";
  }
};

// Polls until pred holds or a second has passed (the device thread runs at
// 1 kHz; a second is generous for a loaded machine).
template <typename Pred>
bool eventually(Pred pred) {
  for (int i = 0; i < 1000; ++i) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return pred();
}

TEST_F(SdlJoystickDeviceTest, NoJoystickIsAClearSentenceNotACrash) {
  const int count = SDL_NumJoysticks();
  SdlJoystickDef def;
  if (count == 0) {
    EXPECT_NE(openError(def).find("no joystick found"), std::string::npos) << openError(def);
  }
  def.index = count + 3;  // absent whatever this machine has plugged in
  const std::string e = openError(def);
  EXPECT_NE(e.find("no joystick"), std::string::npos) << e;
  EXPECT_EQ(e.rfind("SDL joystick: ", 0), 0u) << e;
}

TEST_F(SdlJoystickDeviceTest, AJoystickWithoutForceFeedbackIsRefusedWhenForceIsRequired) {
  const int index = SDL_JoystickAttachVirtual(SDL_JOYSTICK_TYPE_GAMECONTROLLER, 3, 4, 0);
  ASSERT_GE(index, 0) << SDL_GetError();
  SdlJoystickDef def;
  def.index = index;
  const std::string e = openError(def);
  EXPECT_NE(e.find("has no force feedback"), std::string::npos) << e;
  def.mapping.axisZ = 5;  // the virtual stick has 3 axes
  def.requireForceFeedback = false;
  const std::string axes = openError(def);
  EXPECT_NE(axes.find("has 3 axes; the mapping uses axis 5"), std::string::npos) << axes;
  SDL_JoystickDetachVirtual(index);
}

TEST_F(SdlJoystickDeviceTest, InputOnlyStickFollowsItsAxesAndReportsAnUnplug) {
  const int index = SDL_JoystickAttachVirtual(SDL_JOYSTICK_TYPE_GAMECONTROLLER, 3, 4, 0);
  ASSERT_GE(index, 0) << SDL_GetError();
  SDL_Joystick* hand = SDL_JoystickOpen(index);  // the test's handle, to move the virtual stick
  ASSERT_NE(hand, nullptr);

  SdlJoystickDef def;
  def.index = index;
  def.requireForceFeedback = false;
  def.mapping.deadZone = 0.0;
  def.mapping.reach = 0.05;
  SdlJoystickDevice d(def);
  ASSERT_TRUE(d.open()) << d.error();
  EXPECT_FALSE(d.spec().hasForceOutput);
  d.read(0.0);
  EXPECT_EQ(d.error(), nullptr) << d.error();

  SDL_JoystickSetVirtualAxis(hand, 0, 32767);   // full right
  SDL_JoystickSetVirtualAxis(hand, 1, -32767);  // full forward (away from the user)
  SDL_JoystickSetVirtualButton(hand, 2, 1);
  DeviceReading r;
  EXPECT_TRUE(eventually([&] {
    r = d.read(0.0);
    return r.position.x() > 0.0499 && r.position.y() > 0.0499;
  })) << r.position.transpose();
  EXPECT_EQ(r.buttons, 1u << 2);
  d.sendForce(Vec3(1.0, 0.0, 0.0));  // no force output: taken and ignored

  SDL_JoystickDetachVirtual(index);
  EXPECT_TRUE(eventually([&] {
    d.read(0.0);
    return d.error() != nullptr;
  }));
  EXPECT_NE(std::string(d.error()).find("was disconnected"), std::string::npos) << d.error();
  d.close();
  SDL_JoystickClose(hand);
}

// A gamepad without SDL_Haptic but with motors: taken (input only) when
// rumble may stand in for the force, and rumble() reaches its motors at the
// strength asked for (SDL's virtual joystick records what it is sent).
std::atomic<int> gRumbleLow{-1}, gRumbleHigh{-1};
int recordRumble(void*, Uint16 low, Uint16 high) {
  gRumbleLow = low;
  gRumbleHigh = high;
  return 0;
}

TEST_F(SdlJoystickDeviceTest, AGamepadThatRumblesIsTakenAndRumblesAtTheStrengthAsked) {
  SDL_VirtualJoystickDesc desc{};
  desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
  desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
  desc.naxes = 3;
  desc.nbuttons = 4;
  desc.Rumble = &recordRumble;
  const int index = SDL_JoystickAttachVirtualEx(&desc);
  ASSERT_GE(index, 0) << SDL_GetError();
  SdlJoystickDef def;
  def.index = index;
  EXPECT_FALSE(SdlJoystickDevice(def).open());  // force required, rumble not accepted: refused as before
  def.acceptRumble = true;
  SdlJoystickDevice d(def);
  ASSERT_TRUE(d.open()) << (d.error() ? d.error() : "");
  EXPECT_FALSE(d.spec().hasForceOutput);
  EXPECT_TRUE(d.rumble(0.5));
  EXPECT_EQ(gRumbleLow.load(), 32768);
  EXPECT_EQ(gRumbleHigh.load(), 32768);
  EXPECT_TRUE(d.rumble(7.0));  // clamped to full
  EXPECT_EQ(gRumbleLow.load(), 65535);
  EXPECT_TRUE(d.rumble(std::nan("")));  // nothing known: off
  EXPECT_EQ(gRumbleLow.load(), 0);
  d.close();
  SDL_JoystickDetachVirtual(index);
}

TEST_F(SdlJoystickDeviceTest, AStickWithoutMotorsSaysItCannotRumble) {
  const int index = SDL_JoystickAttachVirtual(SDL_JOYSTICK_TYPE_GAMECONTROLLER, 3, 4, 0);
  ASSERT_GE(index, 0) << SDL_GetError();
  SdlJoystickDef def;
  def.index = index;
  def.requireForceFeedback = false;
  SdlJoystickDevice d(def);
  ASSERT_TRUE(d.open()) << (d.error() ? d.error() : "");
  EXPECT_FALSE(d.rumble(0.5));
  d.close();
  SDL_JoystickDetachVirtual(index);
}

}  // namespace
}  // namespace hemiroll::haptics
