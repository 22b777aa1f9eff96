#pragma once
// What a finished (or running) trial amounts to, for scoring, results files
// and the `hemiroll run` line. Filled by TrialSummaryAccumulator; handed to a
// level's score function as a table with the snake_case names below
// (docs/LEVELS.md, "Scoring").

#include <string>
#include <vector>

#include "engine/task/TaskJudge.h"

namespace hemiroll::task {

struct TrialSummary {
  TrialOutcome outcome = TrialOutcome::Running;  // `success` (boolean) in Lua
  std::string reason;                            // `reason`
  double time = 0.0;            // `time`: simulated seconds until the end (or so far) [s]
  long long ticks = 0;          // `ticks`: judged ticks
  int stagesPassed = 0;         // `stages_passed`
  int stageCount = 0;           // `stage_count`
  std::vector<double> stageTimes;  // when each passed stage was passed [s] (results.csv's stage_times_s)
  double contactPath = 0.0;     // `contact_path`: path length of (u_a, v_a) on the plane [m]
  double pointPath = 0.0;       // `point_path`: path length of p = (x_p, y_p) on the face [m]
  // `effort`: integral of |F_h|^2 dt, F_h the coupling force on the mass
  // point (trapezoid over ticks) [N^2 s].
  double effort = 0.0;
  // `smoothness`: mean of |j|^2 over ticks, j the proxy's jerk by the third
  // backward difference of its position over equal ticks [m^2/s^6]; lower is
  // smoother; 0 until four ticks have been seen.
  double smoothness = 0.0;
  // `best_margin`: the largest, over ticks, of the worst normalized margin of
  // the current stage (1 = every component exactly on target, 0 = the worst
  // one on its band's edge, < 0 outside). How close the trial came. [-]
  double bestMargin = 0.0;
  // `final_margin`: the worst normalized margin at the end [-].
  double finalMargin = 0.0;
  // `final_components` (table keyed by variable name, each {error, margin,
  // tolerance}): the current stage's components at the end.
  std::vector<ComponentStatus> finalComponents;
};

}  // namespace hemiroll::task
