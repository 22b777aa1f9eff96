#pragma once
// What the servo loop hands to a recorder: one RecordRow every recordEvery
// ticks (the history unit's time series), one TickInput every tick (the
// device reading and the tick's lateness) and one AppliedCommand per command
// the tick applied (these two make a replay). Plain values only, so that both are trivially
// copyable and cross to the recorder's thread through an SpscRing as bytes.
// The rings are owned by the caller (engine/record or a test) and only
// pointed to by ServoLoopDef; the tick pushes and never waits: a full ring
// costs the row, which the loop counts (ServoLoop::recordDropped()).

#include <array>
#include <cstdint>

#include "engine/haptics/EngagementRamp.h"
#include "engine/haptics/ForceSafety.h"
#include "engine/haptics/ServoCommand.h"
#include "engine/haptics/ServoSnapshot.h"
#include "engine/haptics/SpscRing.h"
#include "engine/physics/DomainEvents.h"

namespace hemiroll::haptics {

struct RecordRow {
  double time = 0.0;                 // simulation time after the tick [s]
  std::uint64_t tick = 0;            // ticks run since start (the first tick is 1)
  std::array<double, 12> state{};    // the 12-state (physics/StateLayout.h)
  Triple proxyPosition{};            // scene [m]
  Triple proxyVelocity{};            // scene [m/s]
  Triple handForce{};                // F_h on the mass point, scene [N]
  Triple modelForce{};               // f: the part of F_h the model receives, scene [N]
  Triple renderedForce{};            // sent to the device, device frame, after safety [N]
  Triple guidanceForce{};            // guidance's part of the desired force, scene, before safety [N]
  double proxyDistance = 0.0;        // proxy to mass point [m]
  double injectedEnergy = 0.0;       // energy watchdog's observation [J]
  double rampScale = 0.0;            // engagement ramp [0, 1]
  double lateness = 0.0;             // this tick's start after its deadline [s] (0 headless)
  physics::DomainEvent event = physics::DomainEvent::None;
  Engagement engagement = Engagement::Disengaged;
  SafetyFault fault = SafetyFault::None;
  bool paused = false;
  bool forceClamped = false;
};

// The device reading one tick used (what HapticDevice::read returned), in
// device coordinates, and the lateness the tick was given (the loop-overrun
// watchdog reads it): with the commands, enough to replay the tick exactly.
struct TickInput {
  std::uint64_t tick = 0;            // the tick that read it (the first tick is 1)
  Triple position{};                 // [m]
  Triple velocity{};                 // [m/s]
  std::uint32_t buttons = 0;
  bool fresh = true;
  bool newPath = false;              // DeviceReading::newPath
  std::int64_t latenessNs = 0;       // [ns], 0 headless
};

// A command as the loop applied it, at the start of `tick`.
struct AppliedCommand {
  std::uint64_t tick = 0;
  ServoCommand command;
};

// 4096 rows: 4 s of slack at 1 kHz recording (41 s at 100 Hz) before a
// stalled writer costs a row; about 1.1 MB, allocated once by the owner.
using RecordRing = SpscRing<RecordRow, 4096>;
// 8192 inputs: 8 s of slack at 1 kHz; about 0.6 MB.
using InputRing = SpscRing<TickInput, 8192>;
// Commands are rare (a few per trial); 256 is four command rings' worth.
using CommandRing = SpscRing<AppliedCommand, 256>;

inline RecordRow recordRowOf(const ServoSnapshot& s) {
  RecordRow r;
  r.time = s.time;
  r.tick = s.tick;
  r.state = s.state;
  r.proxyPosition = s.proxyPosition;
  r.proxyVelocity = s.proxyVelocity;
  r.handForce = s.handForce;
  r.modelForce = s.modelForce;
  r.renderedForce = s.renderedForce;
  r.guidanceForce = s.guidanceForce;
  r.proxyDistance = s.proxyDistance;
  r.injectedEnergy = s.injectedEnergy;
  r.rampScale = s.rampScale;
  r.lateness = s.lateness;
  r.event = s.event;
  r.engagement = s.engagement;
  r.fault = s.fault;
  r.paused = s.paused;
  r.forceClamped = s.forceClamped;
  return r;
}

}  // namespace hemiroll::haptics
