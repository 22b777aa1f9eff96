#pragma once
// Runs several rose-drive scenarios at once, with RK4 in SIMD lanes
// (physics::RoseBatch), each giving exactly the rows and summary that
// ScenarioRun gives it alone: the lanes have the scalar bits, the same
// domain check runs after each step, and a lane whose step leaves the domain
// is handed to the scalar Stepper, which takes that step again (the same
// bits) and locates the event, while the other lanes go on.
//
// Eligible: the rose drive, the fixed-step "rk4" integrator and the contact
// angles (the sweep's runs); anything else runs through ScenarioRun.

#include <cstddef>
#include <functional>
#include <vector>

#include "engine/task/ScenarioDef.h"
#include "game/research/sim/ScenarioRun.h"

namespace hemiroll::game {

class RoseLockstepRun {
 public:
  using LaneRowCallback = std::function<void(std::size_t lane, const TrajectoryRow&)>;

  static bool eligible(const task::ScenarioDef& scenario, const RunSettings& settings);

  // What a row holds, as ScenarioRun's (ScenarioRun.h): the StateOnly rows
  // cost a sweep ~8 % less (issue 32); their position comes from the lanes'
  // own evaluation of the rose.
  using RowContent = game::RowContent;

  // Every scenario eligible; width is a lane width this CPU runs
  // (physics::laneWidthSupported). Throws std::invalid_argument otherwise.
  RoseLockstepRun(std::vector<task::ScenarioDef> scenarios, const RunSettings& settings, int width,
                  RowContent content = RowContent::Full);

  // Rows of lane i in the order ScenarioRun::run gives them (lanes interleaved).
  std::vector<RunSummary> run(const LaneRowCallback& onRow) const;

 private:
  std::vector<task::ScenarioDef> scenarios_;
  RunSettings settings_;
  int width_;
  RowContent content_;
};

}  // namespace hemiroll::game
