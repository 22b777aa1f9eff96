#pragma once
// Commands into the servo loop, through a lock-free SPSC ring; applied at the
// start of the next tick, in order.

#include <array>

#include "engine/physics/ForceCoupling.h"

namespace hemiroll::haptics {

enum class ServoCommandKind {
  Engage,       // arm the engagement (starts when the proxy reaches the mass point)
  Disengage,    // fade the force out, then release the model
  SetCoupling,  // new method and gains (coupling)
  ResetState,   // state and time restart from state, time; clears a halt
  Pause,        // stop the physics, force to zero at once
  Resume,       // run again
  ClearFault,   // unlatch a safety fault (the loop stays paused until Resume)
};

struct ServoCommand {
  ServoCommandKind kind = ServoCommandKind::Pause;
  physics::CouplingDef coupling{};  // SetCoupling
  std::array<double, 12> state{};   // ResetState
  double time = 0.0;                // ResetState [s]
};

}  // namespace hemiroll::haptics
