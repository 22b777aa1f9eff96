#include "engine/script/SweepLoader.h"

#include <lua.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "engine/physics/IntegratorRegistry.h"
#include "engine/script/DataFileLoader.h"
#include "engine/script/LevelFieldChecks.h"
#include "engine/script/LuaTableReader.h"

namespace hemiroll::script {

namespace {

// What messages call a sweep spec and what its chunk returns.
constexpr DataFileKind kSweepFile{"sweep spec", "sweep spec"};

constexpr std::initializer_list<const char*> kParamNames = {"R", "m_s", "m_p", "g", "r1", "r2", "k", "Omega"};
constexpr std::initializer_list<const char*> kStarts = {"rest", "equilibrium"};
constexpr int kMaxRangeCount = 100000;
// duration / dt above this is a typo (1e-9 for 1e-3), not a sweep.
constexpr double kMaxStepsPerPoint = 1e7;

// "" when `value` is allowed for `param`, else what it must be.
std::string valueProblem(SweepParam param, double value) {
  switch (param) {
    case SweepParam::R: return value > 0.0 ? "" : "R must be a positive radius in metres";
    case SweepParam::m_s: return value > 0.0 ? "" : "m_s must be a positive mass in kilograms";
    case SweepParam::m_p: return value >= 0.0 ? "" : "m_p must be a mass >= 0 in kilograms";
    case SweepParam::g: return value >= 0.0 ? "" : "g must be >= 0 (m/s^2)";
    case SweepParam::r1: return value >= 0.0 ? "" : "r1 must be a length >= 0 in metres";
    case SweepParam::r2: return value >= 0.0 ? "" : "r2 must be a length >= 0 in metres";
    case SweepParam::k:
    case SweepParam::Omega: return "";  // any finite number (the reader refuses the rest)
  }
  return "";
}

void checkValue(const LuaTableReader& table, const std::string& key, SweepParam param, double value) {
  if (const std::string problem = valueProblem(param, value); !problem.empty())
    table.fail(key, problem);
}

// The base values of the listed parameters, each checked as an axis value is.
void readBaseValues(const LuaTableReader& table, std::initializer_list<const char*> keys, SweepDef& def) {
  for (const char* key : keys) {
    const SweepParam param = *findSweepParam(key);
    if (const auto v = table.number(key)) {
      checkValue(table, key, param, *v);
      setSweepParam(param, *v, def.params, def.rose);
    }
  }
}

void readParams(const LuaTableReader& top, SweepDef& def) {
  const auto table = top.table("params");
  if (!table) return;  // the paper's values
  rejectUnknownLevelKeys(*table, {"R", "m_s", "m_p", "g"});
  readBaseValues(*table, {"R", "m_s", "m_p", "g"}, def);
}

void readDrive(const LuaTableReader& top, SweepDef& def) {
  const auto table = top.table("drive");
  if (!table) return;  // the paper's rose
  rejectUnknownLevelKeys(*table, {"kind", "r1", "r2", "k", "Omega"});
  if (const auto kind = table->string("kind"); kind && *kind != "rose")
    table->fail("kind", "a sweep runs the rose drive only; leave kind out or write \"rose\", got '" + *kind + "'");
  readBaseValues(*table, {"r1", "r2", "k", "Omega"}, def);
}

void readAnalysis(const LuaTableReader& top, SweepDef& def) {
  const auto table = top.table("analysis");
  if (!table) return;
  rejectUnknownLevelKeys(*table, {"min_rate", "relative_band", "absolute_band", "min_steady_fraction",
                                  "max_relative_spread"});
  SweepAnalysisDef& a = def.analysis;
  const auto nonNegative = [&](const char* key, double fallback, const char* unit) {
    const double v = table->number(key, fallback);
    if (v < 0.0) table->fail(key, std::string("must be >= 0 (") + unit + ")");
    return v;
  };
  a.minRate = nonNegative("min_rate", a.minRate, "rad/s");
  a.relativeBand = nonNegative("relative_band", a.relativeBand, "a fraction of the rate");
  a.absoluteBand = nonNegative("absolute_band", a.absoluteBand, "rad/s");
  a.minSteadyFraction = nonNegative("min_steady_fraction", a.minSteadyFraction, "a share of the run");
  if (a.minSteadyFraction > 1.0) table->fail("min_steady_fraction", "must be at most 1 (a share of the run)");
  a.maxRelativeSpread = nonNegative("max_relative_spread", a.maxRelativeSpread, "a fraction of the rate");
}

SweepStart readStart(const LuaTableReader& top) {
  const auto start = top.string("start");
  if (!start || *start == "equilibrium") return SweepStart::Equilibrium;
  if (*start == "rest") return SweepStart::Rest;
  const char* near = nearestName(*start, kStarts);
  top.fail("start", "unknown start '" + *start + "'" +
                        (near ? " (did you mean '" + std::string(near) + "'?)" : " (expected \"rest\" or \"equilibrium\")"));
}

void readRun(const LuaTableReader& top, SweepDef& def) {
  def.duration = readPositive(top, "duration", "seconds").value_or(def.duration);
  def.timeStep = readPositive(top, "dt", "seconds").value_or(def.timeStep);
  if (def.duration / def.timeStep > kMaxStepsPerPoint)
    top.fail("dt", "duration / dt is more than 10 million steps per point; is dt in seconds?");
  def.integrator = top.string("integrator").value_or(def.integrator);
  const auto& registry = physics::IntegratorRegistry::builtin();
  if (!registry.contains(def.integrator)) {
    std::string names;
    for (const auto& info : registry.list()) names += (names.empty() ? "" : ", ") + info.name;
    top.fail("integrator", "unknown integrator '" + def.integrator + "' (available: " + names + ")");
  }
  def.tolerance = readPositive(top, "tol", "a tolerance").value_or(def.tolerance);
  if (!(def.tolerance >= 1e-15 && def.tolerance <= 1.0)) top.fail("tol", "must be in 1e-15 .. 1 (no double step meets less)");
}

// Pushes list[i] and returns its reader; the caller restores the stack.
LuaTableReader entry(const LuaTableReader& list, int i) {
  lua_checkstack(list.state(), 2);
  lua_rawgeti(list.state(), list.index(), i);
  return LuaTableReader(list.state(), -1, list.source(), list.fieldPath(positionKey(i)));
}

// A list (positions 1..n and nothing else) of at least one entry.
int listLength(const LuaTableReader& list, const std::string& what) {
  const int count = list.entryCount();
  if (count == 0) list.fail("", "empty; give at least one " + what);
  if (static_cast<int>(lua_rawlen(list.state(), list.index())) != count)
    list.fail("", "expected a list of " + what + "s { ..., ... }");
  return count;
}

void readValues(const LuaTableReader& values, SweepAxis& axis) {
  const int count = listLength(values, "value");
  // An axis longer than a range may be is refused before it is read.
  if (count > kMaxRangeCount)
    values.fail("", std::to_string(count) + " values; an axis may have at most " + std::to_string(kMaxRangeCount));
  std::set<double> seen;  // the repeat check in n log n
  for (int i = 1; i <= count; ++i) {
    const auto v = values.numberAt(i);
    if (!v) values.fail(positionKey(i), "expected a number");
    checkValue(values, positionKey(i), axis.param, *v);
    if (!seen.insert(*v).second) values.fail(positionKey(i), "repeats an earlier value; each value once");
    axis.values.push_back(*v);
  }
}

void readRange(const LuaTableReader& range, SweepAxis& axis) {
  rejectUnknownLevelKeys(range, {"from", "to", "count", "log"});
  const auto from = range.number("from"), to = range.number("to");
  if (!from) range.fail("from", "missing; a range needs from, to and count");
  if (!to) range.fail("to", "missing; a range needs from, to and count");
  const auto count = readInteger(range, "count", 2, kMaxRangeCount);
  if (!count) range.fail("count", "missing; a range needs from, to and count (a whole number >= 2)");
  if (*from == *to) range.fail("to", "equals from; for one value write values = { v }");
  checkValue(range, "from", axis.param, *from);
  checkValue(range, "to", axis.param, *to);
  axis.log = readBool(range, "log").value_or(false);
  if (axis.log && !(*from * *to > 0.0))
    range.fail("log", "a log range needs from and to of the same sign, neither 0");
  const int n = *count;
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(n - 1);
    double v = axis.log ? *from * std::pow(*to / *from, t) : *from + (*to - *from) * t;
    if (i == n - 1) v = *to;  // the end exactly as written
    axis.values.push_back(v);
  }
}

SweepAxis readAxis(const LuaTableReader& table, const std::vector<SweepAxis>& earlier) {
  rejectUnknownLevelKeys(table, {"param", "values", "range", "log"});
  const auto name = table.string("param");
  if (!name) table.fail("param", "missing; name the parameter the axis varies (R, m_s, m_p, g, r1, r2, k or Omega)");
  const auto param = findSweepParam(*name);
  if (!param) {
    const char* near = nearestName(*name, kParamNames);
    table.fail("param", "unknown parameter '" + *name + "'" +
                            (near ? " (did you mean '" + std::string(near) + "'?)"
                                  : " (expected R, m_s, m_p, g, r1, r2, k or Omega)"));
  }
  for (std::size_t i = 0; i < earlier.size(); ++i)
    if (earlier[i].param == *param)
      table.fail("param", "'" + *name + "' is already axis " + std::to_string(i + 1) + "; each parameter once");
  SweepAxis axis;
  axis.param = *param;
  const bool hasValues = table.typeOf("values") != LUA_TNIL, hasRange = table.typeOf("range") != LUA_TNIL;
  if (hasValues == hasRange)
    table.fail(hasValues ? "range" : "", "give either values = { ... } or range = { from = .., to = .., count = .. }");
  if (hasValues) {
    readValues(*table.table("values"), axis);
    // Listed values spaced by factors (masses) are shown on a log scale.
    axis.log = readBool(table, "log").value_or(false);
    if (axis.log && std::any_of(axis.values.begin(), axis.values.end(), [&](double v) { return !(v * axis.values[0] > 0.0); }))
      table.fail("log", "a log axis needs values of one sign, none 0");
  } else {
    if (table.typeOf("log") != LUA_TNIL) table.fail("log", "a range says log inside: range = { ..., log = true }");
    readRange(*table.table("range"), axis);
  }
  return axis;
}

void readAxes(const LuaTableReader& top, SweepDef& def) {
  const auto axes = top.table("axes");
  if (!axes) top.fail("axes", "missing; a sweep needs axes = { {param = \"k\", values = {...}}, ... }");
  const int count = listLength(*axes, "axis");
  long long points = 1;
  for (int i = 1; i <= count; ++i) {
    lua_State* L = top.state();
    const int stackTop = lua_gettop(L);
    if (axes->typeAt(i) != LUA_TTABLE) axes->fail(positionKey(i), "expected an axis table {param = ..., ...}");
    const LuaTableReader table = entry(*axes, i);
    def.axes.push_back(readAxis(table, def.axes));
    points *= static_cast<long long>(def.axes.back().values.size());
    if (points > kMaxSweepPoints)
      table.fail("", "the grid would have more than " + std::to_string(kMaxSweepPoints) + " points; split the sweep");
    lua_settop(L, stackTop);
  }
}

SweepDef readSweep(const LuaTableReader& top) {
  rejectUnknownLevelKeys(top, {"description", "params", "drive", "start", "duration", "dt", "integrator", "tol",
                               "analysis", "axes"});
  SweepDef def;
  def.source = top.source();
  def.description = top.string("description").value_or("");
  readParams(top, def);
  readDrive(top, def);
  def.start = readStart(top);
  readRun(top, def);
  readAnalysis(top, def);
  readAxes(top, def);
  return def;
}

// A sweep spec is data: its sandbox has no require and no random.
DataFileLoader sweepFileLoader(const SandboxLimits& limits) { return DataFileLoader(kSweepFile, limits); }

SweepDef readSweepTable(const DataTable& data) { return readSweep(data.top); }

}  // namespace

SweepDef SweepLoader::loadFile(const std::string& path) const {
  return sweepFileLoader(limits_).loadFile(path, readSweepTable);
}

SweepDef SweepLoader::loadSource(std::string_view source, const std::string& name) const {
  return sweepFileLoader(limits_).loadSource(source, name, readSweepTable);
}

}  // namespace hemiroll::script
