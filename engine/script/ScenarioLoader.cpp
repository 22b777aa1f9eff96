#include "engine/script/ScenarioLoader.h"

#include <lua.hpp>
#include <memory>

#include "engine/physics/IntegratorRegistry.h"
#include "engine/physics/RotationDrivenSystem.h"
#include "engine/task/ConstantProxyTrajectory.h"
#include "engine/script/TaskNames.h"
#include "engine/script/DataFileLoader.h"
#include "engine/script/LuaProxyTrajectory.h"
#include "engine/script/LuaTableReader.h"

namespace hemiroll::script {

namespace {

// What messages call a scenario file and what its chunk returns.
constexpr DataFileKind kScenarioFile{"scenario file", "scenario"};

std::string joinNames(const std::vector<physics::IntegratorInfo>& infos) {
  std::string out;
  for (const auto& info : infos) out += (out.empty() ? "" : ", ") + info.name;
  return out;
}

void readParams(const LuaTableReader& top, physics::HemisphereParams& params) {
  const auto table = top.table("params");
  if (!table) return;  // the paper's values
  table->rejectUnknownKeys({"R", "m_s", "m_p", "g"});
  params.radius = table->number("R", params.radius);
  params.shellMass = table->number("m_s", params.shellMass);
  params.pointMass = table->number("m_p", params.pointMass);
  params.gravity = table->number("g", params.gravity);
}

void readRose(const LuaTableReader& drive, physics::RoseDef& rose) {
  drive.rejectUnknownKeys({"kind", "r1", "r2", "k", "Omega"});
  rose.r1 = drive.number("r1", rose.r1);
  rose.r2 = drive.number("r2", rose.r2);
  rose.k = drive.number("k", rose.k);
  rose.omega = drive.number("Omega", rose.omega);
  if (rose.r1 < 0.0) drive.fail("r1", "must be a non-negative length in metres");
  if (rose.r2 < 0.0) drive.fail("r2", "must be a non-negative length in metres");
}

physics::ForceMethod readMethod(const LuaTableReader& drive) {
  const auto method = drive.string("method");
  if (!method || *method == "M3") return physics::ForceMethod::M3;
  if (*method == "M1") return physics::ForceMethod::M1;
  if (*method == "M2") return physics::ForceMethod::M2;
  drive.fail("method", "unknown method '" + *method + "' (expected \"M1\", \"M2\" or \"M3\")");
}

std::shared_ptr<const physics::ProxyTrajectory> readConstantProxy(const LuaTableReader& proxy) {
  physics::Vec3 position;
  if (proxy.typeAt(1) != LUA_TNIL) {  // positional {x, y, z}
    if (proxy.entryCount() != 3) proxy.fail("", "expected exactly three numbers {x, y, z} (m, base frame)");
    for (int i = 0; i < 3; ++i) {
      const auto v = proxy.numberAt(i + 1);
      if (!v) proxy.fail("", "expected exactly three numbers {x, y, z} (m, base frame)");
      position[i] = *v;
    }
  } else {  // named {x = .., y = .., z = ..}
    proxy.rejectUnknownKeys({"x", "y", "z"});
    const char* names[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      const auto v = proxy.number(names[i]);
      if (!v) proxy.fail(names[i], "missing; a constant proxy needs x, y and z (m, base frame)");
      position[i] = *v;
    }
  }
  return std::make_shared<ConstantProxyTrajectory>(position);
}

std::shared_ptr<const physics::ProxyTrajectory> readProxy(const LuaTableReader& drive,
                                                          const std::shared_ptr<LuaSandbox>& sandbox) {
  static const std::string kExpected =
      "a function t -> x, y, z, vx, vy, vz (m, m/s, base frame) or a table {x, y, z}";
  lua_State* L = drive.state();
  const int type = drive.typeOf("proxy");
  if (type == LUA_TNIL) drive.fail("proxy", "missing; expected " + kExpected);
  if (type == LUA_TFUNCTION) {
    drive.pushField("proxy");
    auto proxy = std::make_shared<LuaProxyTrajectory>(sandbox, drive.fieldPath("proxy"));
    // Evaluate once now, so that a function that returns the wrong things
    // fails before any output is written.
    proxy->at(0.0);
    return proxy;
  }
  if (type == LUA_TTABLE) {
    const auto table = drive.table("proxy");
    return readConstantProxy(*table);
  }
  drive.pushField("proxy");
  const std::string got = describeLuaValue(L, -1);
  lua_pop(L, 1);
  drive.fail("proxy", "expected " + kExpected + ", got " + got);
}

void readProxyDrive(const LuaTableReader& drive, const std::shared_ptr<LuaSandbox>& sandbox, DriveDef& def) {
  drive.rejectUnknownKeys({"kind", "method", "kr", "kv", "alpha", "proxy"});
  def.coupling.method = readMethod(drive);
  def.coupling.stiffness = drive.number("kr", def.coupling.stiffness);
  def.coupling.damping = drive.number("kv", def.coupling.damping);
  def.coupling.alpha = drive.number("alpha", def.coupling.alpha);
  // The field is the drive table's ("kr").
  if (const auto error = physics::couplingError(def.coupling)) drive.fail(error->field, error->message);
  def.proxy = readProxy(drive, sandbox);
}

DriveDef readDrive(const LuaTableReader& top, const std::shared_ptr<LuaSandbox>& sandbox) {
  const auto drive = top.table("drive");
  if (!drive)
    top.fail("drive", "missing; expected {kind = \"free\"}, {kind = \"rose\", ...} or {kind = \"proxy\", ...}");
  const auto kind = drive->string("kind");
  if (!kind) drive->fail("kind", "missing; expected \"free\", \"rose\" or \"proxy\"");

  DriveDef def;
  if (*kind == "free") {
    def.kind = DriveKind::Free;
    drive->rejectUnknownKeys({"kind"});
  } else if (*kind == "rose") {
    def.kind = DriveKind::Rose;
    readRose(*drive, def.rose);
  } else if (*kind == "proxy") {
    def.kind = DriveKind::Proxy;
    readProxyDrive(*drive, sandbox, def);
  } else {
    drive->fail("kind", "unknown drive kind '" + *kind + "' (expected \"free\", \"rose\" or \"proxy\")");
  }
  return def;
}

void readInitial(const LuaTableReader& top, DriveKind kind, physics::ForceDrivenState& initial) {
  initial.setZero();
  const auto table = top.table("initial");
  if (!table) return;
  table->rejectUnknownKeys(
      {"x_p", "y_p", "xd_p", "yd_p", "w_x", "w_y", "w_z", "u_a", "v_a", "u_o", "v_o", "psi"});
  for (int slot = 0; slot < 12; ++slot) {
    const char* name = physics::kStateNames[slot];
    const auto value = table->number(name);
    if (!value) continue;
    if (kind == DriveKind::Rose && slot < physics::force_slot::body)
      table->fail(name,
                  "the rose drive prescribes the mass point (it starts at p(0) = (r1 + r2, 0)); "
                  "leave x_p, y_p, xd_p and yd_p out");
    initial[slot] = *value;
  }
}

std::optional<double> readPositiveSeconds(const LuaTableReader& top, const char* key) {
  const auto value = top.number(key);
  if (value && *value <= 0.0) top.fail(key, "must be a positive number of seconds");
  return value;
}

// Everything here reads raw data from the returned table; the only script
// code that runs is a proxy function, through protected calls.
ScenarioDef readScenario(const DataTable& data) {
  const LuaTableReader& top = data.top;
  const std::shared_ptr<LuaSandbox>& sandbox = data.sandbox;
  top.rejectUnknownKeys(
      {"description", "params", "initial", "drive", "duration", "dt", "integrator", "tol", "orientation"});
  ScenarioDef out;
  out.source = top.source();
  (void)top.string("description");
  readParams(top, out.params);
  out.drive = readDrive(top, sandbox);
  // The prescribed drive accepts m_p = 0 (a bare hemisphere); the force
  // drives need a mass for the force to accelerate.
  const bool allowZeroPointMass = out.drive.kind == DriveKind::Rose;
  if (const auto error = physics::paramsError(out.params, allowZeroPointMass)) top.fail(error->field, error->message);
  readInitial(top, out.drive.kind, out.initial);
  out.duration = readPositiveSeconds(top, "duration");
  out.timeStep = readPositiveSeconds(top, "dt");
  out.integrator = top.string("integrator");
  const auto& registry = physics::IntegratorRegistry::builtin();
  if (out.integrator && !registry.contains(*out.integrator))
    top.fail("integrator",
             "unknown integrator '" + *out.integrator + "' (available: " + joinNames(registry.list()) + ")");
  out.tolerance = top.number("tol");
  // Below 1e-15 no double step can meet it (as `sim --tol`).
  if (out.tolerance && !(*out.tolerance >= 1e-15 && *out.tolerance <= 1.0)) top.fail("tol", "must be in 1e-15 .. 1");
  out.orientation = top.string("orientation");
  physics::OrientationForm form;
  if (out.orientation && !physics::parseOrientationForm(*out.orientation, form))
    top.fail("orientation", "must be 'angles' or 'quaternion', got '" + *out.orientation + "'");
  if (out.orientation && out.drive.kind == DriveKind::Rose && form == physics::OrientationForm::Quaternion)
    top.fail("orientation", "the rose drive integrates the 8-state prescribed model; 'quaternion' applies to free and proxy drives");
  return out;
}

}  // namespace

ScenarioDef ScenarioLoader::loadFile(const std::string& path) const {
  return DataFileLoader(kScenarioFile, limits_).loadFile(path, readScenario);
}

ScenarioDef ScenarioLoader::loadSource(std::string_view source, const std::string& name) const {
  return DataFileLoader(kScenarioFile, limits_).loadSource(source, name, readScenario);
}

}  // namespace hemiroll::script
