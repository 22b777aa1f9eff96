#pragma once
// The settle law that comes to rest and stays (docs/AUTOPILOT.md, "Coming
// to rest"): a linear-quadratic regulator on the engine's own model,
// linearised about the rest at a small lean, computed once per body,
// coupling and servo period, and applied every tick by rotating the state
// into the rest's direction (the model is symmetric about the vertical).
//
// Why a regulator: after a landing the light shell rocks under the heavy
// mass point at about 88 rad/s (the paper's body; measured: the
// linearisation's fastest pair), and the coupling's damper hardly touches
// that rocking because the mass point hardly moves; left alone it decays
// with a time constant of about 12 s, while the paper's omega band (0.01
// rad/s) is a tenth of its amplitude after a landing. The regulator moves
// the proxy by micrometres in phase with it and takes it out in a few
// tenths of a second, and holds the lean, the mass point and the proxy at
// the rest the task wants.
//
// What it cannot do: spin about the symmetry axis is not controllable to
// first order (the linearisation has an eigenvalue 1 there that no gain
// moves: the face is frictionless, so the mass point's load acts along the
// axis), so the rest keeps whatever spin the landing left. That spin is the
// landing's job (the planner judges landings with the regulator running).
//
// The state it feeds back, all horizontal vectors in the base frame (so
// that a rotation about the vertical turns them alike): the face normal's
// horizontal part (the lean), the mass point from the face centre, its
// velocity over the face, the angular velocity (w_z as it is), and the
// proxy from the contact point: 11 numbers.

#include <Eigen/Core>

#include "engine/physics/ForceCoupling.h"
#include "engine/physics/HemisphereParams.h"
#include "engine/physics/PlaneVectors.h"
#include "engine/physics/StateLayout.h"

namespace hemiroll::autopilot {

struct SettleGain {
  static constexpr int kStates = 11;
  using State = Eigen::Matrix<double, kStates, 1>;
  bool valid = false;              // false: no stabilising gain found (the old glide settles)
  Eigen::Matrix<double, 2, kStates> gain = Eigen::Matrix<double, 2, kStates>::Zero();
  State rest = State::Zero();      // the rest leaning along `restHeading` at `restLean`
  double restLean = 0.0;           // |horizontal face normal| there [-]
  double restHeading = 0.0;        // its direction [rad]
  double proxyHeight = 0.0;        // the proxy's height at rest [m]
  double slowest = 0.0;            // the slowest controllable closed-loop time constant [s]
};

struct SettleWeights {
  double lean = 0.01;          // [-] per unit of horizontal face normal
  double point = 0.1;          // [R] the mass point's offset
  double pointSpeed = 0.1;     // [R/s] its speed over the face
  double spin = 0.01;          // [rad/s] each angular velocity component
  double proxy = 0.5;          // [R] the proxy from the contact point
  double step = 1e-5;          // [m] the proxy's move per tick
  double restLean = 0.05;      // lean of the rest linearised about [-]
  double horizon = 10.0;       // [s] the discount's time constant (spin cannot be moved: without it there is no finite cost)
};

// Computed once (milliseconds): the rest found by Gauss-Newton on one tick
// of the model, the linearisation by central differences, the Riccati
// equation by doubling.
SettleGain settleGainFor(const physics::HemisphereParams& params, const physics::CouplingDef& coupling, double dt,
                         const SettleWeights& weights = {});

// The regulator's coordinates of state x with the proxy at `proxy` (scene).
SettleGain::State settleCoordinates(const physics::ModelConstants& constants, const physics::ForceDrivenState& x,
                                    const physics::Vec2& proxy);

// The proxy's move this tick towards the rest with horizontal face normal
// `lean` (|lean| = sin of the tilt, pointing from c_up to the contact), at
// most `most` [m]. No allocation.
physics::Vec2 settleStep(const SettleGain& gain, const physics::ModelConstants& constants,
                         const physics::ForceDrivenState& x, const physics::Vec2& proxy, const physics::Vec2& lean,
                         double most);

}  // namespace hemiroll::autopilot
