#pragma once
// One sampled instant of a headless run: what a CSV row holds.

#include "engine/physics/StateLayout.h"

namespace hemiroll::game {

struct TrajectoryRow {
  double time = 0.0;                                              // t [s]
  physics::ForceDrivenState state = physics::ForceDrivenState::Zero();  // the 12-state (rose: p from the curve)
  double energy = 0.0;                                            // T + V [J]
  physics::Vec2 faceForce = physics::Vec2::Zero();   // f on the mass point, face coordinates [N]
  physics::Vec3 handForce = physics::Vec3::Zero();   // F_h, base frame [N] (proxy drives only)
};

}  // namespace hemiroll::game
