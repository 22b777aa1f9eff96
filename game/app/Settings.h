#pragma once
// What the player sets on the settings and research screens. Held by the App
// and kept between runs in settings.json (SettingsFile.h).

#include <optional>
#include <string>

#include "engine/physics/ForceCoupling.h"
#include "engine/render/RenderScene.h"
#include "game/app/KeyBindings.h"

namespace hemiroll::game {

struct Settings {
  // Input device: "mouse", "joystick" (SDL force feedback) or "udp" (a
  // haptic device behind the UDP bridge, docs/UDP_BRIDGE.md).
  std::string device = "mouse";
  int joystickIndex = 0;       // SDL joystick index
  int udpPort = 47110;         // the bridge's port on 127.0.0.1
  // Force method and gains: the level's unless overridden.
  bool overrideCoupling = false;
  int method = 2;              // 0 M1, 1 M2, 2 M3 (the paper's), 3 visual only
  double stiffness = 250.0;    // [N/m]
  double damping = 10.0;       // [N s/m]
  double alpha = 2.0;          // M3's alpha [-]
  double volume = 0.6;         // [0, 1]
  bool vsync = true;
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

// The coupling the play session uses: the level's, or the player's override
// applied to it (validated by the servo loop when posted).
physics::CouplingDef couplingFor(const Settings& settings, const physics::CouplingDef& level);
const char* methodLabel(int method);  // "M1", "M2", "M3", "visual"

}  // namespace hemiroll::game
