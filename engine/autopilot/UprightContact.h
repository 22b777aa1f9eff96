#pragma once
// Where the contact point would be if the hemisphere were rolled straight
// back upright (along the great circle from its lowest body point to the
// contact): c_up = c - R theta k_h / |k_h|, theta the tilt, k_h the horizontal
// part of the face normal.
//
// Why it matters: a straight roll leaves c_up where it is, and any roll
// without spin moves it only at third order in the tilt, so tilting towards
// the target brings the contact point there but not upright. Only spin about
// the vertical (precession) moves c_up at first order: it is the quantity the
// helix has to carry to the target. Once c_up is on the target, a straight
// roll to upright ends there (autopilot/HelixPolicy.h, "land").

#include "engine/physics/HemisphereParams.h"
#include "engine/physics/StateLayout.h"

namespace hemiroll::autopilot {

struct UprightContact {
  physics::Vec2 point;  // c_up on the plane [m]
  double tilt = 0.0;    // angle between the face normal and the vertical [rad]
};

UprightContact uprightContact(const physics::ModelConstants& constants, const physics::ForceDrivenState& x);

// The face normal in the base frame.
physics::Vec3 faceNormal(const physics::ModelConstants& constants, const physics::ForceDrivenState& x);

}  // namespace hemiroll::autopilot
