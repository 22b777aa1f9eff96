#pragma once
// Spin taken out by a law (docs/AUTOPILOT.md, "Taking spin out: the
// brake"). At rest the hemisphere keeps its spin: the linearisation about
// any rest has an eigenvalue 1 there (SettleRegulator.h), and measured on
// the model, the spin the rest keeps (J, w_z once at rest) also survives
// every small motion: a helix of 0.5 mm circles faded out at any rate,
// swirls of the proxy about a fixed point at 1-120 rad/s (off the rocking's
// resonance), a hand held sideways of the lean. They change w_z while they
// last and give it back when they end.
//
// What does change J is a large helix stopped: circle the contact (no
// steering) until the helix settles onto its limit cycle, then stop the
// hand dead. The stop leaves J changed by an amount in the circle's own
// sense that grows steeply with the helix's tilt (on the paper's body
// +0.004, +0.026, +0.098 rad/s at tilts 0.19, 0.30, 0.44 rad, from 1, 1.5
// and 2 mm circles), and it adds to the J there was (measured: the same
// change from J = 0 and J = 0.05 rad/s to 1e-3). So the law is a table:
// the change a stop leaves, by circle size, found once per body and
// coupling by rolling the brake out on the model; a spin J is taken out by
// the circle against it whose change is |J|.
//
// The table, the rollouts and the choice run off the servo tick (once per
// autopilot and per decision); the brake itself is HelixPolicy's circle,
// a few flops a tick.

#include <array>

#include "engine/autopilot/HelixPolicy.h"
#include "engine/autopilot/SettleRegulator.h"
#include "engine/physics/ForceCoupling.h"
#include "engine/physics/HemisphereParams.h"

namespace hemiroll::autopilot {

struct SpinBrakeDef {
  static constexpr int kSizes = 9;
  // Circle sizes tried, smallest first [m]: the paper's body needs 1-2 mm,
  // lighter points or stiffer couplings tilt less per mm and need 3-8 mm.
  std::array<double, kSizes> amplitudes{0.001, 0.0015, 0.002, 0.0025, 0.003, 0.004, 0.005, 0.006, 0.008};
  double rate = 3.14159;  // the circle's pace, the helix's [rad/s]
  // Circling before the stop: the helix reaches its limit cycle (on the
  // paper's body a 1.5 mm circle stopped after 1.5-2 s left 40 % more than
  // after 3 or 5 s, which agree) [s].
  double lock = 3.0;
  double settle = 4.0;    // after the stop, before the rest's spin is read [s]
  double largestTilt = 0.6;  // a size whose helix tilts further is not used (the runaway's road) [rad]
};

struct SpinBrakeTable {
  int rows = 0;  // usable sizes (0: no brake for this body)
  std::array<double, SpinBrakeDef::kSizes> amplitude{};  // [m]
  std::array<double, SpinBrakeDef::kSizes> change{};     // J after the stop, from J = 0, circling anticlockwise [rad/s]
  double rate = 0.0, lock = 0.0;
};

// Rolls the brake out on the model from rest upright for each size: stops
// at the first that leaves the domain, tilts past largestTilt, or changes J
// less than the size before it. `helix` as the autopilot's law has it (its
// hand's stiffening included), `gain` the settle regulator's.
SpinBrakeTable spinBrakeTableFor(const physics::HemisphereParams& params, const physics::CouplingDef& coupling,
                                 const HelixParams& helix, const SettleGain& gain, double dt,
                                 const SpinBrakeDef& def = {});

struct SpinBrakeCommand {
  bool valid = false;
  double amplitude = 0.0;  // [m]
  double rate = 0.0;       // [rad/s], against the spin
  double lock = 0.0;       // [s]
  double change = 0.0;     // the change of J expected [rad/s]
};

// The brake for a rest spinning at `spin` [rad/s]: the circle against it,
// its size interpolated in the table (linearly in the change, from 0 at no
// circle); beyond the table's largest change, the largest (brake again).
SpinBrakeCommand spinBrakeFor(const SpinBrakeTable& table, double spin);

// Starts `command` on `law` (HelixPolicy::brake).
void startBrake(HelixPolicy& law, const SpinBrakeCommand& command);

}  // namespace hemiroll::autopilot
