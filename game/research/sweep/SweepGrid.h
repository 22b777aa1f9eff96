#pragma once
// The points of a sweep (engine/script SweepDef): point i's axis positions,
// its parameters and its start. Point 0 has every axis at its first value;
// the last axis varies fastest. Pure arithmetic on the spec: any thread, any
// shard computes the same point for the same index.

#include <vector>

#include "engine/physics/HemisphereParams.h"
#include "engine/physics/RoseDrive.h"
#include "engine/task/ScenarioDef.h"
#include "engine/task/SweepDef.h"

namespace hemiroll::game {

struct SweepPoint {
  long long index = 0;
  std::vector<int> position;          // per axis, the index into its values
  physics::HemisphereParams params;
  physics::RoseDef rose;
  double startTilt = 0.0;             // [rad] tilt at t = 0 (0 from rest); u_o(0) = -startTilt
};

class SweepGrid {
 public:
  explicit SweepGrid(task::SweepDef def);

  const task::SweepDef& def() const { return def_; }
  long long size() const { return size_; }
  // index in [0, size()).
  SweepPoint point(long long index) const;
  // The scenario that runs the point: the rose drive from its start.
  task::ScenarioDef scenario(const SweepPoint& point) const;

 private:
  task::SweepDef def_;
  long long size_;
};

}  // namespace hemiroll::game
