#pragma once
// What a bot sees each tick, as plain numbers. The host (the trial loop)
// fills it from the servo loop's state; BotScript copies it into one Lua
// table that is built once and reused, so a tick allocates nothing.
//
// Frames: "scene" is the physics base frame (x, y on the plane, z up) [m];
// "face" coordinates are the paper's p = (x_p, y_p) on the flat face.
// Task fields are whatever the level declares; unset targets are NaN-free:
// targetSet says which of the twelve state slots carry a target.

#include <array>
#include <string>

#include "engine/physics/ForceCoupling.h"
#include "engine/physics/HemisphereParams.h"
#include "engine/physics/PlaneZone.h"
#include "engine/script/BotMemory.h"

namespace hemiroll::script {

using Triple3 = std::array<double, 3>;

struct BotObservation {
  double time = 0.0;                 // simulation time [s]
  std::array<double, 12> state{};    // the 12-state, physics/StateLayout.h order and names
  Triple3 mass{};                    // mass point position, scene [m]
  Triple3 massVelocity{};            // mass point velocity, scene [m/s]
  Triple3 centre{};                  // centre of the flat face (= sphere centre), scene [m]
  Triple3 faceX{}, faceY{}, normal{};  // the face's x, y axes and normal, scene (unit vectors)
  Triple3 contact{};                 // contact point on the plane, scene [m]
  Triple3 proxy{};                   // the proxy the device delivered last tick, scene [m]
  Triple3 force{};                   // coupling force on the mass point, scene [N]
  // What the hand feels: the force the device rendered last tick (coupling
  // and guidance, after the safety layer), turned back into the scene frame [N].
  Triple3 deviceForce{};
  double proxyDistance = 0.0;        // proxy to mass point [m]
  bool engaged = false;              // the coupling is on (the proxy came within reach after engage)
  // The share of the coupling's force acting now: 0 before engagement, then
  // rising to 1 over the engagement ramp (the HUD's "holding, force 50%").
  double forceShare = 0.0;
  // The task (filled from the level's judge; zero and unset without one).
  std::array<double, 12> target{};
  std::array<double, 12> tolerance{};
  std::array<bool, 12> targetSet{};
  bool omegaNormSet = false;         // a band on |omega| (not one of the twelve slots)
  double omegaNormTarget = 0.0, omegaNormTolerance = 0.0;  // [rad/s]
  // Forbidden zones of the task (the contact point must never enter them),
  // the first kMaxZones of them: a circle (centre, radius) or a box (min, max).
  static constexpr int kMaxZones = 8;
  std::array<physics::PlaneZone, kMaxZones> zones{};
  int zoneCount = 0;
  double timeLimit = 0.0;            // [s]; 0 = none
  double holdTime = 0.0;             // how long the target must hold [s]
  double held = 0.0;                 // how long it has held so far [s]
  int stage = 0;                     // index of the current waypoint/target (0-based)
};

// Once per trial, for init(level_info, seed). The model's parameters and
// coupling as the level has them (a built-in bot takes them as they are; a
// Lua bot gets them as numbers and the method's name: BotScript).
struct BotLevelInfo {
  std::string name;                  // the level's name
  std::string file;                  // the level file as given
  physics::HemisphereParams params;  // R, m_s, m_p, g
  physics::CouplingDef coupling;     // method (or visual only), kr, kv, alpha
  double dt = 0.001;                 // servo tick [s]
  double timeLimit = 0.0;            // [s]; 0 = none
  double engageDistance = 0.01;      // the proxy must come this close to the mass point to engage [m]
  double workspaceRadius = 0.1;      // the device's reach about its origin, scene [m] (after mapping)
  Triple3 workspaceCentre{};         // the device origin in the scene [m]
  // In a research session: the trial's place (block, condition, trial in
  // block, group, guidance) and the participant's memory across its trials,
  // which the bot may read and change (nullptr outside a session).
  TrialPlace place;
  BotMemory* memory = nullptr;
};

}  // namespace hemiroll::script
