#include "engine/haptics/devices/sdl/DeviceFactory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <iterator>

#include "engine/task/LevelDef.h"

namespace hemiroll::haptics {
namespace {

TEST(DeviceFactoryTest, EveryBuiltInDeviceIsMadeByItsName) {
  const DeviceFactory f;
  EXPECT_EQ(f.names(), (std::vector<std::string>{"mouse", "mouse-hand", "joystick", "udp", "scripted", "simulated-hand"}));
  for (const std::string& name : f.names()) {
    const DeviceChoice c = f.make(name);
    ASSERT_TRUE(c.device) << name << ": " << c.error;
    EXPECT_EQ(c.error, "");
  }
  EXPECT_FALSE(f.make("mouse").device->spec().hasForceOutput);
  // The mouse's hand feel renders force, to the simulated hand it reads.
  EXPECT_TRUE(f.make(kMouseHandDevice).device->spec().hasForceOutput);
  EXPECT_STREQ(f.make(kMouseHandDevice).device->spec().name, "mouse-hand");
  DeviceOptions bad;
  bad.mouseHand.stiffness = 0.0;
  EXPECT_EQ(f.make(kMouseHandDevice, bad).error, "device 'mouse-hand': mouse-hand: hand stiffness must be a positive number of N/m");
  EXPECT_STREQ(f.make("udp").device->spec().name, "udp bridge");
}

// The names a person plays with are made by the factory, and a level can
// map each of them (per_device): the settings never offer a device the
// factory does not know or a level cannot place.
TEST(DeviceFactoryTest, EveryPlayerDeviceIsMadeAndMappable) {
  const DeviceFactory f;
  const std::vector<std::string> names = f.names();
  for (const char* player : kPlayerDevices) {
    EXPECT_NE(std::find(names.begin(), names.end(), player), names.end()) << player;
    EXPECT_NE(std::find_if(std::begin(task::kMappedDevices), std::end(task::kMappedDevices),
                           [&](const char* mapped) { return std::string(mapped) == player; }),
              std::end(task::kMappedDevices))
        << player;
  }
}

TEST(DeviceFactoryTest, UnknownNamesListTheKnownOnes) {
  const DeviceChoice c = DeviceFactory().make("phantom");
  EXPECT_FALSE(c.device);
  EXPECT_EQ(c.error, "unknown device 'phantom'; known devices: mouse, mouse-hand, joystick, udp, scripted, simulated-hand");
}

TEST(DeviceFactoryTest, OpenFailuresComeBackAsTheDevicesSentence) {
  const DeviceFactory f;
  DeviceOptions o;
  o.udp.bindAddress = "0.0.0.0";
  DeviceChoice c = f.makeAndOpen("udp", o);
  EXPECT_FALSE(c.device);
  EXPECT_NE(c.error.find("refusing to bind 0.0.0.0"), std::string::npos) << c.error;

  setenv("SDL_VIDEODRIVER", "dummy", 1);
  o.joystick.index = 99;
  c = f.makeAndOpen("joystick", o);
  EXPECT_FALSE(c.device);
  EXPECT_NE(c.error.find("SDL joystick: no joystick"), std::string::npos) << c.error;
}

TEST(DeviceFactoryTest, InvalidSettingsAreASentenceNotAThrow) {
  DeviceOptions o;
  o.hand.mass = -1.0;
  const DeviceChoice c = DeviceFactory().make("simulated-hand", o);
  EXPECT_FALSE(c.device);
  EXPECT_NE(c.error.find("device 'simulated-hand': SimulatedHandDevice"), std::string::npos) << c.error;
}

TEST(DeviceFactoryTest, DefaultsHoldStillAndOthersCanRegister) {
  DeviceFactory f;
  const DeviceChoice scripted = f.make("scripted");
  EXPECT_EQ(scripted.device->read(1.0).position, Vec3::Zero());
  const DeviceChoice hand = f.make("simulated-hand");
  EXPECT_EQ(hand.device->read(1.0).position, Vec3::Zero());

  f.add("replay", "a recorded trial's proxy input", [](const DeviceOptions&) {
    return std::make_unique<ScriptedDevice>([](double t) {
      DeviceReading r;
      r.position = Vec3(t, 0.0, 0.0);
      return r;
    });
  });
  EXPECT_EQ(f.names().back(), "replay");
  EXPECT_EQ(f.make("replay").device->read(0.5).position.x(), 0.5);
}

TEST(DeviceFactoryTest, DescriptionsGiveEachSpecWithUnits) {
  const std::string d = DeviceFactory().describe();
  EXPECT_NE(d.find("mouse: "), std::string::npos);
  EXPECT_NE(d.find("maxForce 0 N, maxStiffness 1000 N/m, workspace radius 0.1 m, force output no"), std::string::npos)
      << d;
  EXPECT_NE(d.find("joystick: "), std::string::npos);
  EXPECT_NE(d.find("maxForce 2 N, maxStiffness 300 N/m, workspace radius 0.05 m, force output yes"),
            std::string::npos)
      << d;
}

}  // namespace
}  // namespace hemiroll::haptics
