#pragma once
// What the player sets on the settings and research screens. Held by the App
// and kept between runs in settings.json (SettingsFile.h).

#include <optional>
#include <string>

#include "engine/physics/ForceCoupling.h"
#include "engine/haptics/devices/DeviceNames.h"
#include "engine/render/RenderScene.h"
#include "game/ui/settings/KeyBindings.h"

namespace hemiroll::game {

// How the mouse moves the proxy: the proxy is the pointer (Direct), or a
// simulated hand the pointer pulls through a spring and the coupling force
// pushes, as a force device pushes the hand that holds it (Hand: the
// factory's "mouse-hand", engine/haptics/HandSpring.h).
enum class MouseFeel { Direct, Hand };

struct Settings {
  // Input device: "mouse", "joystick" (SDL force feedback) or "udp" (a
  // haptic device behind the UDP bridge, docs/UDP_BRIDGE.md).
  std::string device = haptics::kMouseDevice;
  int joystickIndex = 0;       // SDL joystick index
  int udpPort = 47110;         // the bridge's port on 127.0.0.1
  // The device behind the bridge: its profile's name (devices/NAME.lua,
  // docs/UDP_BRIDGE.md "Device profiles"); "" = the bridge's own defaults.
  std::string deviceProfile;
  // Force method and gains: the level's unless overridden.
  bool overrideCoupling = false;
  int method = 2;              // 0 M1, 1 M2, 2 M3 (the paper's), 3 visual only
  double stiffness = 250.0;    // [N/m]
  double damping = 10.0;       // [N s/m]
  double alpha = 2.0;          // M3's alpha [-]
  double volume = 0.6;         // [0, 1]
  // The mouse's strokes: proxy millimetres per pixel of motion (the
  // PointerMapping's scale; 0.25 mm/px spans a desk device's 20 cm in 800 px).
  double mouseMmPerPixel = 0.25;
  MouseFeel mouseFeel = MouseFeel::Direct;
  // Substitutes for the force a mouse cannot render (issue 26), each shown
  // whatever the device (a force device's player may want them too): a ring
  // round the proxy that grows and reddens with the coupling force, a quiet
  // tone whose pitch follows it, a red pulse at the screen's edge before the
  // mass point leaves the face, and, on a joystick that has motors, rumble.
  bool strainRing = true;
  bool forceTone = true;
  bool fallWarning = true;
  bool rumble = true;
  bool vsync = true;
  // Frames per second while playing, at most (vsync or not): the window
  // sleeps out the rest, leaving the CPU to the 1 kHz servo thread. Menus
  // draw at most kMenuFps, a paused game kStillFps (App).
  int frameCap = 60;
  // The interface's size: 1 = as designed for a 720-line window; it also
  // grows with the window's height (App: window height / 720 times this).
  double uiScale = 1.0;
  render::CameraMode camera = render::CameraMode::Follow;
  double zoom = 1.0;
  double orbitYaw = -0.6;      // the orbit camera's heading of the eye [rad] (arrow keys turn it)
  double orbitPitch = 0.55;    // and its elevation [rad], in [0.05, 1.5]
  bool ghost = true;           // race against your best run of a level (its replay, translucent)
  KeyBindings keys;            // what the keys do while playing
  // Research session (ResearchScreen): who plays, and which session of theirs.
  std::string participant = "player";
  std::string sessionId = "1";
};

// The ranges the settings file and screen accept (inclusive).
inline constexpr double kMouseMmPerPixel[2] = {0.02, 2.0};  // [mm/px]
inline constexpr int kFrameCapFps[2] = {20, 240};           // [frames/s]
inline constexpr double kUiScale[2] = {0.5, 3.0};           // [-]

// The coupling the play session uses: the level's, or the player's override
// applied to it (validated by the servo loop when posted).
physics::CouplingDef couplingFor(const Settings& settings, const physics::CouplingDef& level);
// The device the play session opens (a DeviceFactory name): the settings'
// device, the mouse as "mouse-hand" with the hand feel.
std::string playDeviceName(const Settings& settings);
const char* methodLabel(int method);  // "M1", "M2", "M3", "visual"

}  // namespace hemiroll::game
