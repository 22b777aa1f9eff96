#pragma once
// A warning before the mass point leaves the face (issue 26: a screen pulse
// for a player who cannot feel the force). The engine ends a trial with
// "mass point left the face" when the point on the face disc reaches its
// edge, |p| >= maxPointRadius R (physics::DomainEvents, LeftFace); the face
// is frictionless, so the point does not lift off, it slides out. Run ahead
// at its velocity on the face, (xd_p, yd_p), it reaches the edge after
// timeToEdge; the warning is on when that is within the horizon (0.3 s:
// about a person's visual reaction, HUMAN_MODEL.md, so that a warning seen
// can still be answered). Pure arithmetic on the state: the window calls it
// every frame, tests every tick.

#include <limits>

#include "engine/physics/StateLayout.h"

namespace hemiroll::game {

struct FaceExitForecastDef {
  double horizon = 0.3;         // [s] warn when the edge is this near at the present velocity
  double maxPointRadius = 1.0;  // the face's edge as a fraction of R (DomainLimits' default)
};

struct FaceExitForecast {
  bool warn = false;
  // [s] at the present velocity; 0 at or past the edge; infinity when the
  // point stands still or the state is not finite (no warning from nothing).
  double timeToEdge = std::numeric_limits<double>::infinity();
};

FaceExitForecast forecastFaceExit(const physics::ForceDrivenState& state, double radius,
                                  const FaceExitForecastDef& def = {});

}  // namespace hemiroll::game
