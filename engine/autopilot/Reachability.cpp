#include "engine/autopilot/Reachability.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hemiroll::autopilot {

namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char text[200];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

// Smallest |value| inside the band [target - tol, target + tol].
double nearestToZero(double target, double tol) { return std::max(0.0, std::abs(target) - tol); }

}  // namespace

std::string unreachableReason(const Goal& goal, const physics::HemisphereParams& params, const Workspace& workspace) {
  const double R = params.radius;
  // The proxy stays within about R of the contact point and must stay inside
  // the device's sphere; keep 1 cm for the circle and the steering offset.
  if (goal.contactSet()) {
    const double x = goal.set[7] ? nearestToZero(goal.target[7] - workspace.centre.x(), goal.tolerance[7]) : 0.0;
    const double y = goal.set[8] ? nearestToZero(goal.target[8] - workspace.centre.y(), goal.tolerance[8]) : 0.0;
    const double reach = workspace.radius - 0.01;
    if (std::hypot(x, y) > reach)
      return format("the target contact point is %.3f m from the device's centre, beyond its reach of %.3f m",
                    std::hypot(x, y), reach);
  }
  const double rim = 0.5 * M_PI;
  for (int slot : {9, 10}) {
    if (goal.set[static_cast<std::size_t>(slot)] &&
        nearestToZero(goal.target[static_cast<std::size_t>(slot)], goal.tolerance[static_cast<std::size_t>(slot)]) >= rim)
      return format("the target tilt of %.3f rad is past the rim (pi/2)", goal.target[static_cast<std::size_t>(slot)]);
  }
  const double px = goal.set[0] ? nearestToZero(goal.target[0], goal.tolerance[0]) : 0.0;
  const double py = goal.set[1] ? nearestToZero(goal.target[1], goal.tolerance[1]) : 0.0;
  if (std::hypot(px, py) >= R) return format("the target mass point is %.4f m from the face centre, off the face (R = %.3f m)", std::hypot(px, py), R);

  // At rest with the mass point held at distance d, the tilt solves
  // m_p cos t (d - R sin t) = (3R/8) m_s sin t (physics-notes), so a resting
  // tilt t needs d(t) = R sin t + (3R/8)(m_s/m_p) tan t.
  const bool atRest = goal.set[4] && goal.set[5] && goal.set[6];
  if (atRest && (goal.set[9] || goal.set[10]) && goal.set[0] && goal.set[1]) {
    const double tiltX = goal.set[9] ? nearestToZero(goal.target[9], goal.tolerance[9]) : 0.0;
    const double tiltY = goal.set[10] ? nearestToZero(goal.target[10], goal.tolerance[10]) : 0.0;
    const double tilt = std::min(std::hypot(tiltX, tiltY), rim - 1e-6);
    const double needed = R * std::sin(tilt) + 0.375 * R * params.shellMass / params.pointMass * std::tan(tilt);
    const double allowed = std::hypot(std::abs(goal.target[0]) + goal.tolerance[0], std::abs(goal.target[1]) + goal.tolerance[1]);
    if (needed > allowed)
      return format("the stage asks for rest at a tilt of %.3f rad, which needs the mass point %.4f m off centre, but p "
                    "must stay within %.4f m",
                    tilt, needed, allowed);
  }
  return {};
}

}  // namespace hemiroll::autopilot
