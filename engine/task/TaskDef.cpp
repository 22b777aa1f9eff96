#include "engine/task/TaskDef.h"

namespace hemiroll::task {

namespace {

constexpr const char* kNames[kTaskVariableCount] = {"x_p", "y_p", "xd_p", "yd_p", "w_x", "w_y",        "w_z",
                                                    "u_a", "v_a", "u_o",  "v_o",  "psi", "omega_norm"};

using V = TaskVariable;
constexpr TaskVariableGroup kGroups[] = {
    {"p", 2, {V::x_p, V::y_p, V::x_p}},
    {"p_dot", 2, {V::xd_p, V::yd_p, V::xd_p}},
    {"omega", 3, {V::w_x, V::w_y, V::w_z}},
    {"u_ca", 2, {V::u_a, V::v_a, V::u_a}},
    {"u_co", 2, {V::u_o, V::v_o, V::u_o}},
};

}  // namespace

const char* taskVariableUnitTag(TaskVariable variable) {
  switch (variable) {
    case TaskVariable::x_p: case TaskVariable::y_p: case TaskVariable::u_a: case TaskVariable::v_a: return "m";
    case TaskVariable::xd_p: case TaskVariable::yd_p: return "m_per_s";
    case TaskVariable::w_x: case TaskVariable::w_y: case TaskVariable::w_z: case TaskVariable::omega_norm:
      return "rad_per_s";
    case TaskVariable::u_o: case TaskVariable::v_o: case TaskVariable::psi: return "rad";
  }
  return "?";
}

const char* taskVariableName(TaskVariable variable) {
  const int index = static_cast<int>(variable);
  return index >= 0 && index < kTaskVariableCount ? kNames[index] : "?";
}

std::optional<TaskVariable> taskVariableFromName(std::string_view name) {
  for (int i = 0; i < kTaskVariableCount; ++i)
    if (name == kNames[i]) return static_cast<TaskVariable>(i);
  return std::nullopt;
}

std::optional<TaskVariableGroup> taskVariableGroup(std::string_view name) {
  for (const TaskVariableGroup& group : kGroups)
    if (name == group.name) return group;
  return std::nullopt;
}

}  // namespace hemiroll::task
