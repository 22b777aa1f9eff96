#pragma once
// What the judge's components mean to a player, in a player's words (issue
// 27): not "spin x off by +8.25 °/s" (a rolling rate, its sign the
// physics'), but what to do, in screen directions where there is one:
// "contact point: roll 41.0 mm down-left (±4.0)", "rolling at 8.25 °/s: let
// it settle (±0.57)", the band in brackets in the unit of the number before it.
// The judged variables are grouped as a player sees them: the contact point
// (u_a, v_a), the mass point on the face (x_p, y_p; it turns with the face,
// so it has a distance and no screen direction), its speed, the rolling rate
// (w_x, w_y), the turning rate (w_z), the tilt (u_o, v_o), the heading (psi)
// and the spin (|omega|). The full table (PlayHud, I) keeps the physics names.
//
// No allocation on the HUD's path: rows are written into fixed buffers.

#include <array>
#include <span>
#include <string>

#include "engine/task/TaskDef.h"
#include "engine/task/TaskJudge.h"

namespace hemiroll::game {

struct AdviceRow {
  std::array<char, 128> text{};  // e.g. "contact point: roll 41.0 mm down-left (±4.0)": the band in brackets, in the unit before it
  double margin = 1.0;           // the worst normalized margin of its components
  bool inside = true;            // every component of the group inside its band
};

// The groups present in `components`, one row each, in the order of the
// groups above; returns how many were written (at most out.size()).
// `screenRightHeading` [rad] turns plane directions into screen ones
// (render::screenRightHeading of the camera).
int adviceRows(std::span<const task::ComponentStatus> components, double screenRightHeading,
               std::span<AdviceRow> out);

// The group's name as a player says it ("contact point", "tilt", ...).
const char* playerGroupName(task::TaskVariable variable);

// A move on screen [any unit] as a direction: "right", "up-left", ... ("up"
// is away from the camera, where the mouse's forward stroke goes).
const char* screenDirectionWords(double right, double up);

// The stage's task, short enough to stay on screen: "Goal: the contact point
// onto the green square, then upright, still, the mass point in the middle;
// hold 1.0 s". `index` is 0-based; a multi-stage task says which stage.
std::string taskGoal(const task::StageDef& stage, int index, int count);

}  // namespace hemiroll::game
