#pragma once
// A warning before the mass point leaves the face (issue 26: a screen pulse
// for a player who cannot feel the force). The engine ends a trial with
// "mass point left the face" when the point on the face disc reaches its
// edge, |p| >= maxPointRadius R (physics::DomainEvents, LeftFace); the face
// is frictionless, so the point does not lift off, it slides out. The
// warning is on when either
//   - run ahead at its present velocity on the face (xd_p, yd_p), the point
//     reaches the edge within `horizon` (0.3 s: about a person's visual
//     reaction, HUMAN_MODEL.md, so that a warning seen can still be
//     answered), or
//   - with its present acceleration along the face held too, it reaches the
//     edge within `accelerationHorizon` (0.15 s). On a steep face the point
//     starts from rest and slides out in a tenth of a second, before its
//     velocity says anything. Held longer the acceleration lies: the
//     coupling's spring turns it round within about a quarter of the mass
//     point's period on it (the paper's 1 kg on 250 N/m: 0.1 s), and a
//     0.3 s run at the acceleration of a calm helix's stir (0.75 m/s^2)
//     "leaves" a face it never leaves (measured: 23 false warnings in the
//     autopilot's 13 s on the paper's task).
// Pure arithmetic on the state: the window calls it every frame, tests
// every tick.

#include <limits>

#include "engine/physics/HemisphereParams.h"
#include "engine/physics/StateLayout.h"

namespace hemiroll::game {

struct FaceExitForecastDef {
  double horizon = 0.3;              // [s] at the present velocity
  double accelerationHorizon = 0.15; // [s] with the present acceleration held
  double maxPointRadius = 1.0;       // the face's edge as a fraction of R (DomainLimits' default)
};

struct FaceExitForecast {
  bool warn = false;
  // At the present velocity [s]: 0 at or past the edge; infinity when the
  // point stands still or the input is not finite (no warning from nothing).
  double timeToEdge = std::numeric_limits<double>::infinity();
  // With the acceleration held [s], searched within accelerationHorizon
  // only; infinity beyond it.
  double timeToEdgeAccelerating = std::numeric_limits<double>::infinity();
};

// `acceleration`: the point's along the face, in the face's (x_p, y_p)
// axes [m/s^2] (faceAcceleration; zero: the velocity alone).
FaceExitForecast forecastFaceExit(const physics::ForceDrivenState& state, double radius,
                                  const physics::Vec2& acceleration = physics::Vec2::Zero(),
                                  const FaceExitForecastDef& def = {});

// What gravity and the coupling force on the mass point (F_h, base frame
// [N]) do to it along the face [m/s^2], in the face's axes. The face's own
// turning (the rotating frame's terms) is left out: small while the
// hemisphere moves calmly, and when it does not the warning is due anyway.
physics::Vec2 faceAcceleration(const physics::ForceDrivenState& state, const physics::HemisphereParams& params,
                               const physics::Vec3& forceOnPoint);

}  // namespace hemiroll::game
