#pragma once
// How a scenario drives the mass point (docs/SCENARIOS.md, "Drives").

#include <memory>

#include "engine/physics/ForceCoupling.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/RoseDrive.h"

namespace hemiroll::task {

enum class DriveKind {
  Free,   // no external force: the 12-state model, mass point free on the face
  Rose,   // the 8-state prescribed drive along the paper's rose curve (Sec. 5)
  Proxy,  // the 12-state model coupled (M1/M2/M3) to a proxy trajectory
};

struct DriveDef {
  DriveKind kind = DriveKind::Free;
  physics::RoseDef rose;          // kind == Rose; defaults are the paper's Sec. 5 values
  physics::CouplingDef coupling;  // kind == Proxy; defaults are the paper's Sec. 4 gains, M3
  // kind == Proxy: the proxy as a function of time. May be backed by a Lua
  // function, in which case it keeps its Lua state alive and may throw
  // ScriptError from at() when the script fails at run time.
  std::shared_ptr<const physics::ProxyTrajectory> proxy;
};

inline const char* driveKindName(DriveKind kind) {
  switch (kind) {
    case DriveKind::Free: return "free";
    case DriveKind::Rose: return "rose";
    case DriveKind::Proxy: return "proxy";
  }
  return "?";
}

}  // namespace hemiroll::task
