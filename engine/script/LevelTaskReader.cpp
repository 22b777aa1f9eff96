#include "engine/script/LevelTaskReader.h"

#include <lua.hpp>

#include <algorithm>
#include <string>

#include "engine/script/LevelFieldChecks.h"

namespace hemiroll::script {

namespace {

constexpr std::initializer_list<const char*> kTargetNames = {
    "x_p", "y_p", "xd_p", "yd_p", "w_x", "w_y", "w_z", "u_a", "v_a", "u_o", "v_o", "psi",
    "omega_norm", "p", "p_dot", "omega", "u_ca", "u_co"};

// Adds the components of one `name = {value = .., tol = ..}` entry.
void readTarget(const LuaTableReader& targets, const std::string& name, StageDef& stage) {
  const auto entry = targets.table(name.c_str());
  if (!entry) return;
  rejectUnknownLevelKeys(*entry, {"value", "tol"});
  std::array<TaskVariable, 3> members{};
  int size = 1;
  if (const auto group = taskVariableGroup(name)) {
    members = group->members;
    size = group->size;
  } else {
    members[0] = *taskVariableFromName(name);
  }
  std::array<double, 3> value{}, tolerance{};
  const std::string vectorWhat = size == 2 ? "a list of 2 numbers" : "a list of 3 numbers";
  for (const char* key : {"value", "tol"}) {
    std::array<double, 3>& out = std::string(key) == "value" ? value : tolerance;
    const int type = entry->typeOf(key);
    if (type == LUA_TNIL) entry->fail(key, "missing (every target needs value and tol)");
    if (type == LUA_TNUMBER && (size == 1 || std::string(key) == "tol")) {
      out.fill(*entry->number(key));  // one tolerance for every component
    } else if (size == 2) {
      const auto v = readVector<2>(*entry, key, ("a list of 2 numbers for " + name).c_str());
      std::copy(v->begin(), v->end(), out.begin());
    } else if (size == 3) {
      const auto v = readVector<3>(*entry, key, ("a list of 3 numbers for " + name).c_str());
      std::copy(v->begin(), v->end(), out.begin());
    } else {
      entry->fail(key, "expected a number for " + name + ", got a " + std::string(lua_typename(entry->state(), type)));
    }
  }
  for (int i = 0; i < size; ++i) {
    if (tolerance[static_cast<std::size_t>(i)] <= 0.0)
      entry->fail("tol", "every tolerance must be > 0 (a half-width in the variable's unit)");
    const TaskVariable variable = members[static_cast<std::size_t>(i)];
    const bool taken = std::any_of(stage.targets.begin(), stage.targets.end(),
                                   [&](const TargetDef& t) { return t.variable == variable; });
    if (taken)
      targets.fail(name, std::string("sets ") + taskVariableName(variable) + " a second time (once per variable)");
    stage.targets.push_back({variable, value[static_cast<std::size_t>(i)], tolerance[static_cast<std::size_t>(i)]});
  }
}

void readTargets(const LuaTableReader& owner, StageDef& stage) {
  const auto targets = owner.table("targets");
  if (!targets) owner.fail("targets", "missing; expected a table such as {u_ca = {value = {0, 0}, tol = 0.004}}");
  rejectUnknownLevelKeys(*targets, kTargetNames);
  for (const char* name : kTargetNames) readTarget(*targets, name, stage);
  if (stage.targets.empty()) targets->fail("", "no targets given");
  std::sort(stage.targets.begin(), stage.targets.end(),
            [](const TargetDef& a, const TargetDef& b) { return a.variable < b.variable; });
}

double readHold(const LuaTableReader& owner, double fallback) {
  const auto hold = owner.number("hold");
  if (hold && *hold < 0.0) owner.fail("hold", "must be >= 0 seconds");
  return hold.value_or(fallback);
}

ZoneDef readZone(const LuaTableReader& zone) {
  ZoneDef out;
  out.name = zone.string("name").value_or("");
  const auto shape = zone.string("shape");
  if (!shape) zone.fail("shape", "missing; expected \"circle\" or \"box\"");
  if (*shape == "circle") {
    rejectUnknownLevelKeys(zone, {"name", "shape", "center", "radius"});
    out.shape = ZoneShape::Circle;
    const auto center = readVector<2>(zone, "center", "{x, y} in metres");
    if (!center) zone.fail("center", "missing; expected {x, y} in metres");
    out.center = *center;
    const auto radius = readPositive(zone, "radius", "m");
    if (!radius) zone.fail("radius", "missing; expected a radius in metres");
    out.radius = *radius;
  } else if (*shape == "box") {
    rejectUnknownLevelKeys(zone, {"name", "shape", "min", "max"});
    out.shape = ZoneShape::Box;
    const auto lo = readVector<2>(zone, "min", "{x, y} in metres");
    const auto hi = readVector<2>(zone, "max", "{x, y} in metres");
    if (!lo) zone.fail("min", "missing; expected the lower-left corner {x, y} in metres");
    if (!hi) zone.fail("max", "missing; expected the upper-right corner {x, y} in metres");
    if (!((*hi)[0] > (*lo)[0] && (*hi)[1] > (*lo)[1])) zone.fail("max", "must be above and right of min");
    out.min = *lo;
    out.max = *hi;
  } else {
    zone.fail("shape", "unknown shape '" + *shape + "' (expected \"circle\" or \"box\")");
  }
  return out;
}

void readFailure(const LuaTableReader& task, FailureDef& failure) {
  const auto fail = task.table("fail");
  if (!fail) return;
  rejectUnknownLevelKeys(*fail, {"tip_over", "off_face", "area"});
  failure.tipOver = readBool(*fail, "tip_over").value_or(failure.tipOver);
  failure.offFace = readBool(*fail, "off_face").value_or(failure.offFace);
  if (const auto area = fail->table("area")) failure.area = readZone(*area);
}

void readForbidden(const LuaTableReader& task, std::vector<ZoneDef>& zones) {
  const auto list = task.table("forbidden");
  if (!list) return;
  const int count = list->entryCount();
  // Every zone is tested every tick: a cap keeps a trial's cost bounded.
  if (count > kMaxForbiddenZones)
    list->fail("", std::to_string(count) + " zones; a level may have at most " + std::to_string(kMaxForbiddenZones));
  for (int i = 1; i <= count; ++i)
    if (list->typeAt(i) != LUA_TTABLE) list->fail(positionKey(i), "expected a zone table {shape = ...}");
  if (static_cast<int>(lua_rawlen(list->state(), list->index())) != count)
    list->fail("", "expected a list of zones {shape = ...}, {shape = ...}");
  for (int i = 1; i <= count; ++i) {
    lua_rawgeti(list->state(), list->index(), i);
    zones.push_back(readZone(LuaTableReader(list->state(), -1, list->source(), list->fieldPath(positionKey(i)))));
  }
}

void readStages(const LuaTableReader& task, double defaultHold, std::vector<StageDef>& stages) {
  const auto list = task.table("stages");
  const int count = list->entryCount();
  if (count == 0) list->fail("", "empty; give at least one stage {targets = {...}}");
  if (count > kMaxStages)
    list->fail("", std::to_string(count) + " stages; a level may have at most " + std::to_string(kMaxStages));
  if (static_cast<int>(lua_rawlen(list->state(), list->index())) != count)
    list->fail("", "expected a list of stages {targets = ...}, {targets = ...}");
  for (int i = 1; i <= count; ++i) {
    const std::string at = positionKey(i);
    if (list->typeAt(i) != LUA_TTABLE) list->fail(at, "expected a stage table {targets = {...}}");
    lua_rawgeti(list->state(), list->index(), i);
    const LuaTableReader stage(list->state(), -1, list->source(), list->fieldPath(at));
    rejectUnknownLevelKeys(stage, {"name", "targets", "hold"});
    StageDef def;
    def.name = stage.string("name").value_or("");
    readTargets(stage, def);
    def.hold = readHold(stage, defaultHold);
    stages.push_back(std::move(def));
  }
}

}  // namespace

void readLevelTask(const LuaTableReader& top, TaskDef& task) {
  const auto table = top.table("task");
  if (!table) return;
  rejectUnknownLevelKeys(*table, {"targets", "hold", "time_limit", "stages", "fail", "forbidden"});
  const double hold = readHold(*table, 0.0);
  const bool hasTargets = table->typeOf("targets") != LUA_TNIL;
  const bool hasStages = table->typeOf("stages") != LUA_TNIL;
  if (hasTargets && hasStages)
    table->fail("stages", "give either targets (one stage) or stages, not both");
  if (hasTargets) {
    StageDef stage;
    readTargets(*table, stage);
    stage.hold = hold;
    task.stages.push_back(std::move(stage));
  } else if (hasStages) {
    readStages(*table, hold, task.stages);
  }
  task.timeLimit = readPositive(*table, "time_limit", "s").value_or(task.timeLimit);
  // Longer would be no trial anyone sits through, and its tick count must
  // stay far inside 64 bits.
  if (task.timeLimit > kMaxTimeLimit)
    table->fail("time_limit", "must be at most " + std::to_string(static_cast<int>(kMaxTimeLimit)) + " s (a day)");
  readFailure(*table, task.failure);
  readForbidden(*table, task.forbidden);
}

}  // namespace hemiroll::script
