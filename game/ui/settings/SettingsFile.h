#pragma once
// The player's settings kept between runs: one JSON object in settings.json
// under the user's configuration directory (XDG; HEMIROLL_CONFIG_DIR
// overrides it), SI units in the key names:
//   {"version": 1, "device": "mouse", "udp_port": 47110, "device_profile": "touch", "joystick_index": 0,
//    "override_coupling": false, "method": "M3", "stiffness_N_per_m": 250,
//    "damping_N_s_per_m": 10, "alpha": 2, "volume": 0.6, "mouse_mm_per_px": 0.25,
//    "mouse_feel": "direct", "strain_ring": true, "force_tone": true, "fall_warning": true, "rumble": true,
//    "vsync": true, "frame_cap_fps": 60, "ui_scale": 1,
//    "camera": "follow", "zoom": 1, "ghost": true, "orbit_yaw_rad": -0.6,
//    "orbit_pitch_rad": 0.55, "participant": "player",
//    "keys": {"take_hold": "Space", "let_go": "Backspace", "camera": "Tab",
//             "orbit_left": "Left", ...}}
// Reading never fails the game: a missing file gives the defaults; a key
// with a bad value keeps its default and says so; a file that is not JSON is
// moved aside (never deleted) and the defaults are used. Writing replaces the
// file atomically (engine/record's writeFileAtomically).

#include <filesystem>
#include <string>
#include <vector>

#include "game/ui/settings/Settings.h"

namespace hemiroll::game {

std::filesystem::path configDirectory();

struct LoadedSettings {
  Settings settings;
  std::vector<std::string> notes;  // what was wrong and what was done about it
};

LoadedSettings loadSettings(const std::filesystem::path& file);
// "" when saved, else a sentence naming the file.
std::string saveSettings(const std::filesystem::path& file, const Settings& settings);

// The JSON text of saveSettings (public for tests).
std::string settingsJson(const Settings& settings);

}  // namespace hemiroll::game
