#pragma once
// The paper's task (levels/paper_reaching.lua) as the autopilot's Goal, for
// the autopilot's tests.

#include <cmath>

#include "engine/autopilot/Goal.h"

namespace hemiroll::autopilot::test {

inline Goal paperGoal() {
  Goal g;
  const auto band = [&](int slot, double target, double tol) {
    g.set[static_cast<std::size_t>(slot)] = true;
    g.target[static_cast<std::size_t>(slot)] = target;
    g.tolerance[static_cast<std::size_t>(slot)] = tol;
  };
  for (int slot : {0, 1}) band(slot, 0.0, 0.004);
  for (int slot : {2, 3}) band(slot, 0.0, 0.004);
  for (int slot : {4, 5, 6}) band(slot, 0.0, 0.01);
  band(7, -0.04, 0.004);
  band(8, -0.04, 0.004);
  for (int slot : {9, 10}) band(slot, 0.0, M_PI / 18);
  return g;
}

}  // namespace hemiroll::autopilot::test
