#pragma once
// Targets the autopilot can tell at once it will never reach, so that it
// says so in one line instead of circling until the time limit: a contact
// point beyond the device's reach, a tilt past the rim, a mass point off the
// face, or a stage that asks the hemisphere to rest where it cannot.

#include <string>

#include "engine/autopilot/Goal.h"
#include "engine/physics/HemisphereParams.h"

namespace hemiroll::autopilot {

struct Workspace {
  physics::Vec3 centre = physics::Vec3::Zero();  // scene [m]
  double radius = 0.1;                           // [m]
};

// Empty when nothing rules the goal out; else why, in one sentence.
std::string unreachableReason(const Goal& goal, const physics::HemisphereParams& params, const Workspace& workspace);

}  // namespace hemiroll::autopilot
