#pragma once
// A pure physics run as a scenario file describes it (docs/SCENARIOS.md), in
// plain C++: no Lua types. Fields the file leaves out keep these defaults.

#include <optional>
#include <string>

#include "engine/physics/HemisphereParams.h"
#include "engine/physics/StateLayout.h"
#include "engine/task/DriveDef.h"

namespace hemiroll::task {

struct ScenarioDef {
  std::string source;                // the file as named by the caller, for messages
  physics::HemisphereParams params;  // the paper's values unless the file says otherwise
  // The 12-state initial condition in the order of physics::kStateNames. For
  // the rose drive only slots 4..11 (the hemisphere) are used: the mass
  // point's own state comes from the curve.
  physics::ForceDrivenState initial = physics::ForceDrivenState::Zero();
  DriveDef drive;
  // Defaults for the command-line flags; flags win.
  std::optional<double> duration;        // [s], > 0
  std::optional<double> timeStep;        // `dt` [s], > 0
  std::optional<std::string> integrator;  // a name in physics::IntegratorRegistry
  std::optional<double> tolerance;        // `tol` [-], > 0: adaptive integrators only
  std::optional<std::string> orientation; // "angles" or "quaternion" (physics::OrientationForm)
};

}  // namespace hemiroll::task
