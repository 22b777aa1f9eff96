#pragma once
// The hemisphere's static tilt for the mass point held at distance d from
// the face centre, the start "from the equilibrium state corresponding to
// p(0)" of Svinin et al. 2009, Sec. 5. The hand carries the mass point's
// in-face load, so the tilt theta solves (physics-notes.md)
//   m_p cos(theta) (d - R sin(theta)) = (3R/8) m_s sin(theta).
// The left side minus the right is m_p d > 0 at 0, -(3R/8) m_s < 0 at pi/2
// and decreasing while d - R sin(theta) > 0 (negative beyond), so there is
// exactly one root in [0, pi/2); bisection finds it to the last bit.
// In the contact angles the tilt that lowers the mass point at p = (d, 0) is
// u_o = -theta (v_o = psi = 0); u_o = +theta tips (PrescribedDriveSystemTest).

#include "engine/physics/HemisphereParams.h"

namespace hemiroll::game {

// [rad] in [0, pi/2); 0 for d <= 0, m_p = 0 or g = 0 (gravity makes no torque).
double staticTilt(const physics::HemisphereParams& params, double distance);

}  // namespace hemiroll::game
