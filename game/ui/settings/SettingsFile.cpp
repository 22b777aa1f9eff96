#include "game/ui/settings/SettingsFile.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>

#include "engine/haptics/devices/sdl/DeviceFactory.h"
#include "engine/platform/KeyNames.h"
#include "engine/record/DurableFile.h"
#include "engine/task/ProtocolDef.h"

namespace hemiroll::game {

namespace {

using Json = nlohmann::json;

constexpr const char* kMethods[] = {"M1", "M2", "M3", "visual"};
constexpr const char* kCameras[] = {"follow", "orbit", "top"};
constexpr const char* kMouseFeels[] = {"direct", "hand"};  // MouseFeel's order

template <std::size_t N>
int indexOf(const char* const (&names)[N], const std::string& name) {
  for (std::size_t i = 0; i < N; ++i)
    if (name == names[i]) return static_cast<int>(i);
  return -1;
}

template <std::size_t N>
std::string choices(const char* const (&names)[N]) {
  std::string out;
  for (std::size_t i = 0; i < N; ++i) out += (i == 0 ? "'" : i + 1 == N ? " or '" : ", '") + std::string(names[i]) + "'";
  return out;
}

// Reads each key into the settings when it is present and good; a bad one
// keeps the default and adds a note naming it.
class Reader {
 public:
  Reader(const Json& json, const std::filesystem::path& file, std::vector<std::string>& notes)
      : json_(json), file_(file.string()), notes_(notes) {}

  void number(const char* key, double& target, double min, double max, const char* what) {
    const Json* v = find(key);
    if (!v) return;
    if (!v->is_number() || !std::isfinite(v->get<double>()) || v->get<double>() < min || v->get<double>() > max)
      return bad(key, what);
    target = v->get<double>();
  }
  void integer(const char* key, int& target, int min, int max, const char* what) {
    const Json* v = find(key);
    if (!v) return;
    if (!v->is_number_integer() || v->get<long long>() < min || v->get<long long>() > max) return bad(key, what);
    target = v->get<int>();
  }
  void boolean(const char* key, bool& target) {
    const Json* v = find(key);
    if (!v) return;
    if (!v->is_boolean()) return bad(key, "true or false");
    target = v->get<bool>();
  }
  template <std::size_t N>
  void choice(const char* key, const char* const (&names)[N], int& target) {
    const Json* v = find(key);
    if (!v) return;
    const int i = v->is_string() ? indexOf(names, v->get<std::string>()) : -1;
    if (i < 0) return bad(key, choices(names));
    target = i;
  }
  // "keys": {"take_hold": "Space", ...}. Each named action takes its key
  // unless the name is unknown, Escape, or already taken by an action named
  // before it; then that one keeps its default. Actions not named keep theirs
  // (or give one up to a named action, by KeyBindings::bind's swap).
  void keys(KeyBindings& target) {
    const Json* v = find("keys");
    if (!v) return;
    if (!v->is_object()) return bad("keys", "an object of action: key name");
    KeyBindings wanted;
    std::vector<std::int32_t> taken;
    for (int i = 0; i < kKeyActionCount; ++i) {
      const auto action = static_cast<KeyAction>(i);
      const std::string id = std::string("keys.") + keyActionInfo(action).id;
      const auto it = v->find(keyActionInfo(action).id);
      if (it == v->end()) continue;
      const std::int32_t code = it->is_string() ? platform::keyFromName(it->get<std::string>()) : 0;
      if (!KeyBindings::bindable(code)) {
        bad(id.c_str(), "a key name such as 'Space' or 'H' (not Escape)");
        continue;
      }
      if (std::find(taken.begin(), taken.end(), code) != taken.end()) {
        bad(id.c_str(), "a key no other action has ('" + it->get<std::string>() + "' is taken)");
        continue;
      }
      taken.push_back(code);
      wanted.bind(action, code);
    }
    for (auto it = v->begin(); it != v->end(); ++it)
      if (!knownAction(it.key())) notes_.push_back(file_ + ": 'keys." + it.key() + "' is no action; ignored");
    target = wanted;
  }
  // `allowEmpty`: "" means none (a device profile's name).
  void identifier(const char* key, std::string& target, bool allowEmpty = false) {
    const Json* v = find(key);
    if (!v) return;
    if (!v->is_string() || !(isIdentifier(v->get<std::string>()) || (allowEmpty && v->get<std::string>().empty())))
      return bad(key, "an id of letters, digits, '-' and '_'");
    target = v->get<std::string>();
  }

 private:
  // Ids name folders and files (a session's participant): the protocols' rule.
  static bool isIdentifier(const std::string& s) { return task::isFolderName(s); }
  static bool knownAction(const std::string& id) {
    for (int i = 0; i < kKeyActionCount; ++i)
      if (id == keyActionInfo(static_cast<KeyAction>(i)).id) return true;
    return false;
  }
  const Json* find(const char* key) const {
    const auto it = json_.find(key);
    return it == json_.end() ? nullptr : &*it;
  }
  void bad(const char* key, const std::string& what) {
    notes_.push_back(file_ + ": '" + key + "' must be " + what + "; kept the default");
  }

  const Json& json_;
  std::string file_;
  std::vector<std::string>& notes_;
};

}  // namespace

std::filesystem::path configDirectory() {
  if (const char* d = std::getenv("HEMIROLL_CONFIG_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) return std::filesystem::path(x) / "hemiroll";
  if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".config/hemiroll";
  return std::filesystem::path(".hemiroll");
}

LoadedSettings loadSettings(const std::filesystem::path& file) {
  LoadedSettings out;
  std::error_code ec;
  if (!std::filesystem::exists(file, ec) && !std::filesystem::is_symlink(file, ec)) return out;
  Json json;
  // Settings are a few hundred bytes; a file far larger (or not a file) is
  // not read at all (the checked reader, files::kSettings), so that it
  // cannot cost gigabytes of parsing or hang on a FIFO.
  bool readable = true;
  std::string text;
  try {
    text = record::readWholeFile(file, files::kSettings);
  } catch (const std::exception&) {
    readable = false;
  }
  try {
    if (readable) json = Json::parse(text);
  } catch (const std::exception& e) {
    json = nullptr;
  }
  if (!json.is_object()) {
    // Keep it for the player to look at; start from the defaults.
    const std::filesystem::path aside = file.string() + ".unreadable-" + std::to_string(std::time(nullptr));
    std::filesystem::rename(file, aside, ec);
    out.notes.push_back("the settings file " + file.string() +
                        (readable ? " is not a JSON object; " : " is not a file of at most 1 MiB; ") +
                        (ec ? std::string("it was left in place") : "moved aside to " + aside.string()) +
                        " and the defaults are used");
    return out;
  }
  Settings& s = out.settings;
  Reader r(json, file, out.notes);
  int device = indexOf(haptics::kPlayerDevices, s.device);
  r.choice("device", haptics::kPlayerDevices, device);
  s.device = haptics::kPlayerDevices[device];
  r.integer("udp_port", s.udpPort, 1, 65535, "a port in 1..65535");
  r.identifier("device_profile", s.deviceProfile, /*allowEmpty=*/true);
  r.integer("joystick_index", s.joystickIndex, 0, 63, "a joystick index in 0..63");
  r.boolean("override_coupling", s.overrideCoupling);
  r.choice("method", kMethods, s.method);
  r.number("stiffness_N_per_m", s.stiffness, 1.0, 5000.0, "a stiffness in 1..5000 N/m");
  r.number("damping_N_s_per_m", s.damping, 0.0, 100.0, "a damping in 0..100 N s/m");
  r.number("alpha", s.alpha, 0.1, 10.0, "an alpha in 0.1..10");
  r.number("volume", s.volume, 0.0, 1.0, "a volume in 0..1");
  r.number("mouse_mm_per_px", s.mouseMmPerPixel, kMouseMmPerPixel[0], kMouseMmPerPixel[1],
           "a mouse sensitivity in 0.02..2 mm per pixel");
  int feel = static_cast<int>(s.mouseFeel);
  r.choice("mouse_feel", kMouseFeels, feel);
  s.mouseFeel = static_cast<MouseFeel>(feel);
  r.boolean("strain_ring", s.strainRing);
  r.boolean("force_tone", s.forceTone);
  r.boolean("fall_warning", s.fallWarning);
  r.boolean("rumble", s.rumble);
  r.boolean("vsync", s.vsync);
  r.integer("frame_cap_fps", s.frameCap, kFrameCapFps[0], kFrameCapFps[1], "a frame cap in 20..240 fps");
  r.number("ui_scale", s.uiScale, kUiScale[0], kUiScale[1], "an interface scale in 0.5..3");
  int camera = static_cast<int>(s.camera);
  r.choice("camera", kCameras, camera);
  s.camera = static_cast<render::CameraMode>(camera);
  r.number("zoom", s.zoom, 0.25, 8.0, "a zoom in 0.25..8");
  r.boolean("ghost", s.ghost);
  r.number("orbit_yaw_rad", s.orbitYaw, -1e3, 1e3, "an angle in radians");
  r.number("orbit_pitch_rad", s.orbitPitch, 0.05, 1.5, "an elevation in 0.05..1.5 rad");
  r.identifier("participant", s.participant);
  r.keys(s.keys);
  return out;
}

std::string settingsJson(const Settings& s) {
  Json json = Json::object();
  json["version"] = 1;
  json["device"] = s.device;
  json["udp_port"] = s.udpPort;
  json["device_profile"] = s.deviceProfile;
  json["joystick_index"] = s.joystickIndex;
  json["override_coupling"] = s.overrideCoupling;
  json["method"] = kMethods[s.method >= 0 && s.method < 4 ? s.method : 2];
  json["stiffness_N_per_m"] = s.stiffness;
  json["damping_N_s_per_m"] = s.damping;
  json["alpha"] = s.alpha;
  json["volume"] = s.volume;
  json["mouse_mm_per_px"] = s.mouseMmPerPixel;
  json["mouse_feel"] = kMouseFeels[s.mouseFeel == MouseFeel::Hand ? 1 : 0];
  json["strain_ring"] = s.strainRing;
  json["force_tone"] = s.forceTone;
  json["fall_warning"] = s.fallWarning;
  json["rumble"] = s.rumble;
  json["vsync"] = s.vsync;
  json["frame_cap_fps"] = s.frameCap;
  json["ui_scale"] = s.uiScale;
  json["camera"] = kCameras[static_cast<int>(s.camera)];
  json["zoom"] = s.zoom;
  json["ghost"] = s.ghost;
  json["orbit_yaw_rad"] = s.orbitYaw;
  json["orbit_pitch_rad"] = s.orbitPitch;
  json["participant"] = s.participant;
  Json keys = Json::object();
  for (int i = 0; i < kKeyActionCount; ++i) {
    const auto action = static_cast<KeyAction>(i);
    keys[keyActionInfo(action).id] = s.keys.keyName(action);
  }
  json["keys"] = keys;
  return json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::string saveSettings(const std::filesystem::path& file, const Settings& settings) {
  try {
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    record::writeFileAtomically(file, settingsJson(settings));
    return "";
  } catch (const std::exception& e) {
    return std::string("settings not saved: ") + e.what();
  }
}

}  // namespace hemiroll::game
