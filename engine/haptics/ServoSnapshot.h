#pragma once
// What the servo loop publishes after every tick, for the renderer, the HUD
// and the recorder. Plain arrays only, so that it is trivially copyable and
// crosses threads through the TripleBuffer as bytes.

#include <array>
#include <cstdint>

#include "engine/haptics/EngagementRamp.h"
#include "engine/haptics/ForceSafety.h"
#include "engine/physics/DomainEvents.h"

namespace hemiroll::haptics {

using Triple = std::array<double, 3>;

struct ServoSnapshot {
  std::uint64_t tick = 0;                 // ticks run since start (the first tick is 1)
  double time = 0.0;                      // simulation time [s]
  std::array<double, 12> state{};         // the 12-state (physics/StateLayout.h)
  Triple proxyPosition{};                 // scene [m]
  Triple proxyVelocity{};                 // scene [m/s]
  Triple handForce{};                     // F_h on the mass point, scene [N]
  Triple modelForce{};                    // the part of F_h the model receives, scene [N]
  Triple renderedForce{};                 // sent to the device, device frame, after safety [N]
  Triple guidanceForce{};                 // guidance's part of the desired force, scene, before safety [N]
  double proxyDistance = 0.0;             // proxy to mass point [m]
  double injectedEnergy = 0.0;            // energy watchdog's observation [J]
  physics::DomainEvent event = physics::DomainEvent::None;
  Engagement engagement = Engagement::Disengaged;
  double rampScale = 0.0;                 // [0, 1]
  SafetyFault fault = SafetyFault::None;
  bool paused = false;                    // by command or by a fault
  bool forceClamped = false;              // the clamp shortened this tick's force
  // Timing (zero in headless runs).
  double lateness = 0.0;                  // this tick's start after its deadline [s]
  double maxLateness = 0.0;               // [s] since start
  std::uint64_t missedTicks = 0;          // ticks skipped by the catch-up policy
  std::uint64_t stalls = 0;               // wake-ups later than the safety's maxTickLateness
};

}  // namespace hemiroll::haptics
