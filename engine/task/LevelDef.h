#pragma once
// A level as a level file declares it (docs/LEVELS.md), in plain C++: no Lua
// types. Fields the file leaves out keep these defaults (the paper's Sec. 4
// set-up where the paper has one). The Lua functions a level may carry
// (scoring, callbacks) live in its LevelScript; this struct only records
// which of them exist.

#include <array>
#include <map>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/physics/ForceCoupling.h"
#include "engine/physics/HemisphereParams.h"
#include "engine/physics/StateLayout.h"
#include "engine/task/TaskDef.h"

namespace hemiroll::task {

// Device -> scene, as haptics::WorkspaceMapping (which engine/script must not
// know): p_scene = scale * p_device + offset.
struct DeviceMappingDef {
  double scale = 1.0;                 // scene metres per device metre [-], > 0
  std::array<double, 3> offset{};     // scene position of the device origin [m]
};

// The kinds of device a level may map separately (`device.per_device`): the
// desk mouse, a force-feedback joystick, a real device through the UDP
// bridge, and the bots' scripted device. Names only: what they are is
// engine/haptics' business.
inline constexpr const char* kMappedDevices[] = {"mouse", "joystick", "udp", "bot"};

enum class Medal : std::uint8_t { None, Bronze, Silver, Gold };
const char* medalName(Medal medal);  // "none", "bronze", "silver", "gold"

// Scores are "higher is better"; a medal needs score >= its threshold.
// Without a score function a trial has no score and no medal.
struct ScoringDef {
  bool hasScoreFunction = false;
  double bronze = 0.0, silver = 0.0, gold = 0.0;  // bronze <= silver <= gold
  bool hasMedals = false;                          // the file gave `medals`
};

// What the scene must show and record, so nothing else is computed.
// Scenery: a mesh from the game's assets placed on the plane (visual only:
// nothing collides with it).
struct PropDef {
  std::string mesh;                    // path under assets/ ("meshes/flag.obj"); glTF, GLB or OBJ
  std::array<double, 3> position{};    // base frame: where it stands (its bounding box's bottom middle) [m]
  double size = 0.01;                  // radius of the sphere the mesh is scaled to [m]
  double yaw = 0.0;                    // turn about the vertical [rad]
  std::array<double, 3> colour{1.0, 1.0, 1.0};  // multiplies the mesh's colours, each in [0, 1]
};

struct SceneDef {
  bool contactTrace = true;            // draw the contact point's path on the plane
  std::vector<PropDef> props;          // scenery (docs/LEVELS.md, "scene.props")
  std::vector<std::string> plots;      // channel names (docs/LEVELS.md, "scene.plots")
  // A way to go drawn on the plane, for a tutorial to show (docs/LEVELS.md,
  // "scene.example_path"): points {x, y} [m], at most kMaxExamplePath.
  std::vector<std::array<double, 2>> examplePath;
  static constexpr int kMaxExamplePath = 2000;
  double recordRate = 100.0;           // samples per second a recording keeps [Hz], in (0, 1000]
};

// Lua callbacks: which exist and how often on_update runs.
struct CallbackDef {
  double rate = 20.0;                  // on_update calls per simulated second [Hz], in [10, 100]
  bool onStart = false, onUpdate = false, onSuccess = false, onFail = false;
};

struct LevelDef {
  std::string source;                  // the file as named by the caller, for messages
  std::string name;                    // required
  std::string description;             // what to do and the intended technique
  std::string author;
  int difficulty = 1;                  // 1 (tutorial) .. 5 (research grade)
  std::string version = "1";

  physics::HemisphereParams params;    // the paper's values by default
  // The 12-state initial condition (physics::kStateNames order); omitted = 0.
  physics::ForceDrivenState initial = physics::ForceDrivenState::Zero();
  // force.method "M1" | "M2" | "M3" | "visual" (M3 gains, no rendered force:
  // CouplingDef::visualOnly). Defaults are the paper's M3, kr 250, kv 10, alpha 2.
  physics::CouplingDef coupling;
  DeviceMappingDef mapping;            // every device, unless overridden below
  // Per device kind (kMappedDevices), the fields a level overrides; the rest
  // come from `mapping`.
  std::map<std::string, DeviceMappingDef> deviceMappings;
  const DeviceMappingDef& mappingFor(const std::string& device) const {
    const auto it = deviceMappings.find(device);
    return it == deviceMappings.end() ? mapping : it->second;
  }

  TaskDef task;
  ScoringDef scoring;
  SceneDef scene;
  CallbackDef callbacks;
  // A bot module that plays this level when it is watched ("bots.rose" ->
  // scripts/bots/rose.lua); "" = none. The rose demonstration uses it.
  std::string demoBot;
};

}  // namespace hemiroll::task
