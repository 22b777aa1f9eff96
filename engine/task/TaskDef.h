#pragma once
// The task of a level as plain data (docs/LEVELS.md, "task"): what must be
// reached, how closely, for how long, and what ends a trial early. TaskJudge
// evaluates it natively every tick; no Lua is involved once it is loaded.
//
// Units are SI and those of the state slot: m, m/s, rad/s, rad.

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hemiroll::task {

// A judged quantity: the twelve slots of the 12-state (physics/StateLayout.h,
// same order and names) and |omega|. psi is compared modulo 2 pi (the same
// orientation); every other slot is compared as it is.
enum class TaskVariable : std::uint8_t {
  x_p, y_p, xd_p, yd_p, w_x, w_y, w_z, u_a, v_a, u_o, v_o, psi,
  omega_norm,  // |omega| = sqrt(w_x^2 + w_y^2 + w_z^2) [rad/s]
};
inline constexpr int kTaskVariableCount = 13;

// "x_p", ..., "psi", "omega_norm".
const char* taskVariableName(TaskVariable variable);
// Its unit as a column name carries it: "m", "m_per_s", "rad_per_s", "rad".
const char* taskVariableUnitTag(TaskVariable variable);
// The variable of a name; nullopt for anything else (including group names).
std::optional<TaskVariable> taskVariableFromName(std::string_view name);

// Names that stand for several variables at once in a level file, with a
// vector value: p = {x_p, y_p}, p_dot = {xd_p, yd_p}, omega = {w_x, w_y, w_z},
// u_ca = {u_a, v_a} (contact point on the plane), u_co = {u_o, v_o} (contact
// point on the sphere). The paper's names (Sec. 4).
struct TaskVariableGroup {
  const char* name;
  int size;
  std::array<TaskVariable, 3> members;
};
// The group of a name; nullopt when `name` is not a group.
std::optional<TaskVariableGroup> taskVariableGroup(std::string_view name);

// One judged component: |value(variable) - value| <= tolerance.
struct TargetDef {
  TaskVariable variable = TaskVariable::x_p;
  double value = 0.0;      // target [unit of the variable]
  double tolerance = 0.0;  // half-width of the band [unit of the variable], > 0
};

// One step of a task. A level without `stages` has exactly one stage built
// from task.targets and task.hold. A stage is passed when every target is
// inside its band continuously for `hold` seconds; the next stage starts at
// once; passing the last stage is success.
struct StageDef {
  std::string name;                // for messages ("gate 2"); "" = "stage N"
  std::vector<TargetDef> targets;  // sorted by variable, at most one per variable
  double hold = 0.0;               // [s], >= 0; 0 = the first tick inside passes
};

// A region of the plane, tested against the contact point (u_a, v_a).
enum class ZoneShape : std::uint8_t { Circle, Box };
struct ZoneDef {
  std::string name;               // for messages; "" = "zone N"
  ZoneShape shape = ZoneShape::Circle;
  std::array<double, 2> center{};  // Circle [m]
  double radius = 0.0;             // Circle [m], > 0
  std::array<double, 2> min{};     // Box, lower-left corner [m]
  std::array<double, 2> max{};     // Box, upper-right corner [m], > min
};

struct FailureDef {
  bool tipOver = true;            // the rim touched the plane (physics::DomainEvent::TippedOver)
  bool offFace = true;            // the mass point reached the face's edge (DomainEvent::LeftFace)
  std::optional<ZoneDef> area;    // the contact point must stay inside this zone
  // A non-finite state always fails ("state not finite"): nothing can follow it.
};

// What a level may ask for at most (the loader refuses more): every stage
// and zone is looked at every tick, and the tick count of the time limit
// must fit 64 bits with room to spare.
inline constexpr int kMaxStages = 100;
inline constexpr int kMaxForbiddenZones = 100;
inline constexpr double kMaxTimeLimit = 86400.0;  // [s]

struct TaskDef {
  std::vector<StageDef> stages;        // empty = a watch-only level (below)
  double timeLimit = 240.0;            // [s], > 0; the paper's 4 min by default
  FailureDef failure;
  std::vector<ZoneDef> forbidden;      // entering any of them (contact point) fails
  // A level with no targets (no stages) is watched, not solved: reaching the
  // time limit is success ("watched to the end") instead of failure.
  bool watchOnly() const { return stages.empty(); }
};

}  // namespace hemiroll::task
