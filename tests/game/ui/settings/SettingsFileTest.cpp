#include "game/ui/settings/SettingsFile.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>

#include "engine/platform/KeyNames.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

TEST(SettingsFileTest, AMissingFileGivesTheDefaultsAndNoNote) {
  test::TempDirectory dir;
  const LoadedSettings loaded = loadSettings(dir.path() / "settings.json");
  EXPECT_TRUE(loaded.notes.empty());
  EXPECT_EQ(settingsJson(loaded.settings), settingsJson(Settings{}));
}

TEST(SettingsFileTest, EveryFieldRoundTrips) {
  test::TempDirectory dir;
  Settings s;
  s.device = "udp";
  s.udpPort = 50000;
  s.deviceProfile = "touch_x";
  s.joystickIndex = 2;
  s.overrideCoupling = true;
  s.method = 0;
  s.stiffness = 123.25;
  s.damping = 3.5;
  s.alpha = 1.5;
  s.volume = 0.125;
  s.vsync = false;
  s.camera = render::CameraMode::Top;
  s.zoom = 1.75;
  s.ghost = false;
  s.orbitYaw = 2.25;
  s.orbitPitch = 1.25;
  s.participant = "P-07";
  s.mouseMmPerPixel = 0.125;
  s.frameCap = 144;
  s.uiScale = 1.25;
  s.mouseFeel = MouseFeel::Hand;
  s.strainRing = false;
  s.forceTone = false;
  s.fallWarning = false;
  s.rumble = false;
  ASSERT_TRUE(s.keys.bind(KeyAction::TakeHold, platform::keyFromName("H")));
  ASSERT_TRUE(s.keys.bind(KeyAction::OrbitLeft, platform::keyFromName("Keypad 4")));
  const auto file = dir.path() / "nested" / "settings.json";
  ASSERT_EQ(saveSettings(file, s), "");
  const LoadedSettings back = loadSettings(file);
  EXPECT_TRUE(back.notes.empty());
  EXPECT_EQ(settingsJson(back.settings), settingsJson(s));
  EXPECT_EQ(back.settings.stiffness, 123.25);
  EXPECT_EQ(back.settings.camera, render::CameraMode::Top);
  EXPECT_EQ(back.settings.participant, "P-07");
  EXPECT_EQ(back.settings.deviceProfile, "touch_x");
  EXPECT_EQ(back.settings.keys, s.keys);
  EXPECT_EQ(back.settings.keys.keyName(KeyAction::TakeHold), "H");
  EXPECT_EQ(back.settings.mouseMmPerPixel, 0.125);
  EXPECT_EQ(back.settings.frameCap, 144);
  EXPECT_EQ(back.settings.uiScale, 1.25);
  EXPECT_EQ(back.settings.mouseFeel, MouseFeel::Hand);
  EXPECT_FALSE(back.settings.strainRing);
  EXPECT_FALSE(back.settings.forceTone);
  EXPECT_FALSE(back.settings.fallWarning);
  EXPECT_FALSE(back.settings.rumble);
  EXPECT_THAT(settingsJson(s), HasSubstr("\"mouse_feel\": \"hand\""));
  EXPECT_THAT(settingsJson(s), HasSubstr("\"orbit_left\": \"Keypad 4\""));
  // SI units in the key names.
  EXPECT_THAT(settingsJson(s), HasSubstr("\"stiffness_N_per_m\": 123.25"));
}

// One bad key keeps its default and is named; the good ones still load.
TEST(SettingsFileTest, ABadValueKeepsItsDefaultAndIsNamed) {
  test::TempDirectory dir;
  const std::string file = dir.write("settings.json",
                                     R"({"zoom": -2, "camera": "side", "volume": 0.25, "device": "phantom",
                                         "participant": "../etc", "udp_port": 70000, "vsync": "yes",
                                         "stiffness_N_per_m": 1e30, "frame_cap_fps": 5, "ui_scale": 40,
                                         "mouse_mm_per_px": 0})");
  const LoadedSettings loaded = loadSettings(file);
  EXPECT_EQ(loaded.settings.volume, 0.25);
  EXPECT_EQ(loaded.settings.zoom, Settings{}.zoom);
  EXPECT_EQ(loaded.settings.camera, Settings{}.camera);
  EXPECT_EQ(loaded.settings.device, "mouse");
  EXPECT_EQ(loaded.settings.participant, Settings{}.participant);
  EXPECT_EQ(loaded.settings.udpPort, Settings{}.udpPort);
  EXPECT_EQ(loaded.settings.vsync, Settings{}.vsync);
  std::string all;
  for (const std::string& n : loaded.notes) all += n + "\n";
  EXPECT_EQ(loaded.settings.stiffness, Settings{}.stiffness);
  EXPECT_EQ(loaded.settings.frameCap, Settings{}.frameCap);
  EXPECT_EQ(loaded.settings.uiScale, Settings{}.uiScale);
  EXPECT_EQ(loaded.settings.mouseMmPerPixel, Settings{}.mouseMmPerPixel);
  for (const char* key : {"'zoom'", "'camera'", "'device'", "'participant'", "'udp_port'", "'vsync'",
                          "'stiffness_N_per_m'", "'frame_cap_fps'", "'ui_scale'", "'mouse_mm_per_px'"})
    EXPECT_THAT(all, HasSubstr(key));
  EXPECT_THAT(all, HasSubstr("'follow', 'orbit' or 'top'"));
}

// The force substitutes and the mouse's feel: a bad value keeps the default
// and the note names the key and what it must be.
TEST(SettingsFileTest, BadForceCueSettingsAreRefusedWithTheirKeyNamed) {
  test::TempDirectory dir;
  const std::string file = dir.write("settings.json",
                                     R"({"mouse_feel": "glove", "strain_ring": 1, "force_tone": "loud",
                                         "fall_warning": null, "rumble": [true]})");
  const LoadedSettings loaded = loadSettings(file);
  EXPECT_EQ(loaded.settings.mouseFeel, MouseFeel::Direct);
  EXPECT_TRUE(loaded.settings.strainRing);
  EXPECT_TRUE(loaded.settings.forceTone);
  EXPECT_TRUE(loaded.settings.fallWarning);
  EXPECT_TRUE(loaded.settings.rumble);
  std::string all;
  for (const std::string& n : loaded.notes) all += n + "\n";
  EXPECT_THAT(all, HasSubstr("'mouse_feel' must be 'direct' or 'hand'; kept the default"));
  for (const char* key : {"strain_ring", "force_tone", "fall_warning", "rumble"})
    EXPECT_THAT(all, HasSubstr("'" + std::string(key) + "' must be true or false; kept the default"));
  EXPECT_EQ(loaded.notes.size(), 5u) << all;
}

// Keys by name: an unknown name, Escape, or a key an earlier action already
// has keeps that action's default; the good ones load; an action the game
// does not have is named and ignored. Whatever the file says, no key ends up
// doing two things.
TEST(SettingsFileTest, KeysByNameWithBadOnesNamed) {
  test::TempDirectory dir;
  const std::string file = dir.write("settings.json",
                                     R"({"keys": {"take_hold": "h", "let_go": "Escape", "camera": "H",
                                                  "orbit_up": "NoSuchKey", "orbit_down": 5, "jump": "J",
                                                  "orbit_left": "Space"}})");
  const LoadedSettings loaded = loadSettings(file);
  const KeyBindings& keys = loaded.settings.keys;
  const KeyBindings defaults;
  EXPECT_EQ(keys.keyName(KeyAction::TakeHold), "H");
  EXPECT_EQ(keys.keyName(KeyAction::OrbitLeft), "Space");
  // take_hold took the free H (freeing Space), orbit_left then the free Space
  // (freeing Left); the actions with bad entries keep their defaults.
  EXPECT_EQ(keys.key(KeyAction::LetGo), defaults.key(KeyAction::LetGo));
  EXPECT_EQ(keys.key(KeyAction::CycleCamera), defaults.key(KeyAction::CycleCamera));
  EXPECT_EQ(keys.key(KeyAction::OrbitUp), defaults.key(KeyAction::OrbitUp));
  EXPECT_EQ(keys.key(KeyAction::OrbitDown), defaults.key(KeyAction::OrbitDown));
  for (int i = 0; i < kKeyActionCount; ++i)
    for (int j = i + 1; j < kKeyActionCount; ++j)
      EXPECT_NE(keys.key(static_cast<KeyAction>(i)), keys.key(static_cast<KeyAction>(j))) << i << " " << j;
  std::string all;
  for (const std::string& n : loaded.notes) all += n + "\n";
  for (const char* key : {"'keys.let_go'", "'keys.camera'", "'keys.orbit_up'", "'keys.orbit_down'", "'keys.jump'"})
    EXPECT_THAT(all, HasSubstr(key));
  EXPECT_THAT(all, HasSubstr("'H' is taken"));
  EXPECT_EQ(loaded.notes.size(), 5u) << all;
}

TEST(SettingsFileTest, AFileThatIsNotJsonIsMovedAsideNotDeleted) {
  test::TempDirectory dir;
  const std::string file = dir.write("settings.json", "{ zoom: 2");
  const LoadedSettings loaded = loadSettings(file);
  ASSERT_EQ(loaded.notes.size(), 1u);
  EXPECT_THAT(loaded.notes[0], HasSubstr("moved aside"));
  EXPECT_FALSE(std::filesystem::exists(file));
  int aside = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path()))
    aside += e.path().filename().string().rfind("settings.json.unreadable-", 0) == 0;
  EXPECT_EQ(aside, 1);
  EXPECT_EQ(settingsJson(loaded.settings), settingsJson(Settings{}));
}

TEST(SettingsFileTest, AHugeFileIsMovedAsideUnread) {
  // A 300 MB settings.json once took 1.25 GB to parse (issue 19). A sparse
  // 300 MB file here: were it read, the test would read 300 MB of zeros.
  test::TempDirectory dir;
  const std::string file = dir.write("settings.json", "{}");
  std::filesystem::resize_file(file, std::uintmax_t{300} << 20);
  const LoadedSettings loaded = loadSettings(file);
  ASSERT_EQ(loaded.notes.size(), 1u);
  EXPECT_THAT(loaded.notes[0], HasSubstr("is not a file of at most 1 MiB; moved aside"));
  EXPECT_FALSE(std::filesystem::exists(file));
  EXPECT_EQ(settingsJson(loaded.settings), settingsJson(Settings{}));
}

TEST(SettingsFileTest, AnUnwritableDirectoryIsASentenceNotACrash) {
  test::TempDirectory dir;
  const std::string blocker = dir.write("file", "x");  // a file where a directory would go
  const std::string error = saveSettings(std::filesystem::path(blocker) / "settings.json", Settings{});
  EXPECT_THAT(error, HasSubstr("settings not saved"));
}

TEST(SettingsFileTest, ConfigDirectoryFollowsXdg) {
  const char* savedOwn = std::getenv("HEMIROLL_CONFIG_DIR");
  const char* savedXdg = std::getenv("XDG_CONFIG_HOME");
  const std::string own = savedOwn ? savedOwn : "", xdg = savedXdg ? savedXdg : "";
  setenv("HEMIROLL_CONFIG_DIR", "/some/where", 1);
  EXPECT_EQ(configDirectory(), "/some/where");
  unsetenv("HEMIROLL_CONFIG_DIR");
  setenv("XDG_CONFIG_HOME", "/xdg", 1);
  EXPECT_EQ(configDirectory(), "/xdg/hemiroll");
  if (savedOwn) setenv("HEMIROLL_CONFIG_DIR", own.c_str(), 1);
  if (savedXdg) setenv("XDG_CONFIG_HOME", xdg.c_str(), 1);
  else unsetenv("XDG_CONFIG_HOME");
}

}  // namespace
}  // namespace hemiroll::game
