#include "game/ui/hud/PlayerWords.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "game/ui/hud/HintCompass.h"

namespace hemiroll::game {

namespace {

using task::TaskVariable;
constexpr double kDegrees = 180.0 / std::numbers::pi;

enum class Group : int { Contact, FacePoint, FaceSpeed, Rolling, Turning, Tilt, Heading, Spin };
constexpr int kGroups = 8;

Group groupOf(TaskVariable v) {
  switch (v) {
    case TaskVariable::x_p:
    case TaskVariable::y_p: return Group::FacePoint;
    case TaskVariable::xd_p:
    case TaskVariable::yd_p: return Group::FaceSpeed;
    case TaskVariable::w_x:
    case TaskVariable::w_y: return Group::Rolling;
    case TaskVariable::w_z: return Group::Turning;
    case TaskVariable::u_a:
    case TaskVariable::v_a: return Group::Contact;
    case TaskVariable::u_o:
    case TaskVariable::v_o: return Group::Tilt;
    case TaskVariable::psi: return Group::Heading;
    case TaskVariable::omega_norm: return Group::Spin;
  }
  return Group::Spin;
}

// The second member of a pair (y of x, v of u): its error is the move's second axis.
bool secondOfPair(TaskVariable v) {
  return v == TaskVariable::y_p || v == TaskVariable::yd_p || v == TaskVariable::w_y || v == TaskVariable::v_a ||
         v == TaskVariable::v_o;
}

// What a group's members add up to on one tick.
struct Gathered {
  int members = 0;
  double error[2] = {0.0, 0.0};   // value - target, per axis of the pair [SI]
  bool zeroTargets = true;        // every target 0 (at rest, upright, in the middle)
  double tolerance = 0.0;         // the worst member's band [SI]
  double margin = 1.0;            // the worst normalized margin
  bool inside = true;
};

// One decimal in the player's unit, two for bands narrower than one unit
// (a 0.57 °/s band), so that a number never reads as its band's edge.
int decimalsFor(double toleranceInUnit) { return toleranceInUnit < 1.0 ? 2 : 1; }

void write(AdviceRow& row, Group g, const Gathered& s, double heading) {
  char* out = row.text.data();
  const std::size_t n = row.text.size();
  const char* name = playerGroupName(g == Group::Contact ? TaskVariable::u_a
                                     : g == Group::FacePoint ? TaskVariable::x_p
                                     : g == Group::FaceSpeed ? TaskVariable::xd_p
                                     : g == Group::Rolling   ? TaskVariable::w_x
                                     : g == Group::Turning   ? TaskVariable::w_z
                                     : g == Group::Tilt      ? TaskVariable::u_o
                                     : g == Group::Heading   ? TaskVariable::psi
                                                             : TaskVariable::omega_norm);
  if (s.inside) {
    std::snprintf(out, n, "%s: in its band", name);
    return;
  }
  const double size = std::hypot(s.error[0], s.error[1]);
  switch (g) {
    case Group::Contact: {
      double right = 0.0, up = 0.0;
      toScreenDirections(-s.error[0], -s.error[1], heading, right, up);  // where to go: target - value
      const int d = decimalsFor(s.tolerance * 1e3);
      std::snprintf(out, n, "contact point: roll %.*f mm %s (±%.*f)", d, size * 1e3,
                    screenDirectionWords(right, up), d, s.tolerance * 1e3);
      return;
    }
    case Group::FacePoint: {
      const int d = decimalsFor(s.tolerance * 1e3);
      std::snprintf(out, n, s.zeroTargets ? "mass point: %.*f mm off the face's middle, bring it back (±%.*f)"
                                          : "mass point: %.*f mm off its place on the face (±%.*f)",
                    d, size * 1e3, d, s.tolerance * 1e3);
      return;
    }
    case Group::FaceSpeed: {
      const int d = decimalsFor(s.tolerance * 1e3);
      std::snprintf(out, n, s.zeroTargets ? "mass point sliding at %.*f mm/s: hold it still (±%.*f)"
                                          : "mass point speed %.*f mm/s off its target (±%.*f)",
                    d, size * 1e3, d, s.tolerance * 1e3);
      return;
    }
    case Group::Rolling:
    case Group::Turning:
    case Group::Spin: {
      const int d = decimalsFor(s.tolerance * kDegrees);
      const char* what = g == Group::Rolling ? "rolling" : g == Group::Turning ? "turning" : "spinning";
      if (s.zeroTargets)
        std::snprintf(out, n, "%s at %.*f °/s: let it settle (±%.*f)", what, d, size * kDegrees, d,
                      s.tolerance * kDegrees);
      else
        std::snprintf(out, n, "%s %.*f °/s off its target (±%.*f)", what, d, size * kDegrees, d,
                      s.tolerance * kDegrees);
      return;
    }
    case Group::Tilt: {
      const int d = decimalsFor(s.tolerance * kDegrees);
      std::snprintf(out, n, s.zeroTargets ? "tilted %.*f °: stand it upright (±%.*f)"
                                          : "tilt %.*f ° off the lean it wants (±%.*f)",
                    d, size * kDegrees, d, s.tolerance * kDegrees);
      return;
    }
    case Group::Heading: {
      const int d = decimalsFor(s.tolerance * kDegrees);
      // psi grows anticlockwise seen from above; the move is target - value.
      std::snprintf(out, n, "heading: turn it %.*f ° %s (±%.*f)", d, size * kDegrees,
                    s.error[0] > 0.0 ? "clockwise" : "anticlockwise", d, s.tolerance * kDegrees);
      return;
    }
  }
}

}  // namespace

const char* playerGroupName(TaskVariable v) {
  switch (groupOf(v)) {
    case Group::Contact: return "contact point";
    case Group::FacePoint: return "mass point";
    case Group::FaceSpeed: return "mass point speed";
    case Group::Rolling: return "rolling";
    case Group::Turning: return "turning";
    case Group::Tilt: return "tilt";
    case Group::Heading: return "heading";
    case Group::Spin: return "spin";
  }
  return "?";
}

const char* screenDirectionWords(double right, double up) {
  if (!(std::hypot(right, up) > 0.0)) return "nowhere";
  static constexpr const char* kWords[8] = {"right", "up-right", "up",   "up-left",
                                            "left",  "down-left", "down", "down-right"};
  const double sector = std::atan2(up, right) / (std::numbers::pi / 4.0);  // -4 .. 4, 0 = right
  const int i = static_cast<int>(std::lround(sector) + 8) % 8;
  return kWords[i];
}

int adviceRows(std::span<const task::ComponentStatus> components, double heading, std::span<AdviceRow> out) {
  std::array<Gathered, kGroups> groups{};
  for (const task::ComponentStatus& c : components) {
    Gathered& g = groups[static_cast<std::size_t>(groupOf(c.variable))];
    ++g.members;
    g.error[secondOfPair(c.variable) ? 1 : 0] = c.error;
    g.zeroTargets = g.zeroTargets && c.target == 0.0;
    const double m = c.normalizedMargin();
    if (g.members == 1 || m < g.margin) {
      g.margin = m;
      g.tolerance = c.tolerance;
    }
    g.inside = g.inside && c.inside;
  }
  int rows = 0;
  for (int i = 0; i < kGroups && rows < static_cast<int>(out.size()); ++i) {
    const Gathered& g = groups[static_cast<std::size_t>(i)];
    if (g.members == 0) continue;
    AdviceRow& row = out[static_cast<std::size_t>(rows++)];
    row.margin = g.margin;
    row.inside = g.inside;
    write(row, static_cast<Group>(i), g, heading);
  }
  return rows;
}

std::string taskGoal(const task::StageDef& stage, int index, int count) {
  bool contact = false, still = false, upright = false, middle = false, heading = false;
  double lean = 0.0, pointOff = 0.0, headingTo = 0.0;
  for (const task::TargetDef& t : stage.targets) {
    switch (groupOf(t.variable)) {
      case Group::Contact: contact = true; break;
      case Group::Tilt:
        if (t.value == 0.0) upright = true;
        lean = std::hypot(lean, t.value);
        break;
      case Group::FacePoint:
        middle = true;
        pointOff = std::hypot(pointOff, t.value);
        break;
      case Group::FaceSpeed:
      case Group::Rolling:
      case Group::Turning:
      case Group::Spin: still = still || t.value == 0.0; break;
      case Group::Heading:
        heading = true;
        headingTo = t.value;
        break;
    }
  }
  std::string parts;
  const auto add = [&](const std::string& p) { parts += (parts.empty() ? "" : ", ") + p; };
  char number[64];
  if (lean > 0.0) {
    std::snprintf(number, sizeof number, "leaning %.0f °", lean * kDegrees);
    add(number);
  } else if (upright) {
    add("upright");
  }
  if (still) add("still");
  if (middle) {
    if (pointOff > 0.0) {
      std::snprintf(number, sizeof number, "the mass point %.0f mm off the middle", pointOff * 1e3);
      add(number);
    } else {
      add("the mass point in the middle");
    }
  }
  if (heading) {
    std::snprintf(number, sizeof number, "turned to %.0f °", headingTo * kDegrees);
    add(number);
  }
  std::string goal = count > 1 ? "Stage " + std::to_string(index + 1) + " of " + std::to_string(count) +
                                     (stage.name.empty() ? "" : " (" + stage.name + ")") + ": "
                               : "Goal: ";
  if (contact) goal += parts.empty() ? "the contact point onto the green square" :
                                       "the contact point onto the green square, then " + parts;
  else goal += parts.empty() ? "inside every band" : parts;
  if (stage.hold > 0.0) {
    std::snprintf(number, sizeof number, "; hold %.1f s", stage.hold);
    goal += number;
  }
  return goal;
}

}  // namespace hemiroll::game
