#include "engine/script/LevelLoader.h"

#include <lua.hpp>

#include <cmath>
#include <iterator>

#include "engine/script/DataFileLoader.h"
#include "engine/script/LevelFieldChecks.h"
#include "engine/script/LevelTaskReader.h"
#include "engine/script/LuaTableReader.h"
#include "engine/script/ScriptModules.h"

namespace hemiroll::script {

namespace {

// What messages call a level file and what its chunk returns.
constexpr DataFileKind kLevelFile{"level file", "level"};

constexpr std::initializer_list<const char*> kPlotChannels = {
    "x_p", "y_p", "xd_p", "yd_p", "w_x", "w_y", "w_z", "u_a", "v_a", "u_o", "v_o", "psi",
    "omega_norm", "energy", "proxy_x", "proxy_y", "proxy_z", "force_x", "force_y", "force_z", "force_norm"};

void readMeta(const LuaTableReader& top, LevelDef& def) {
  const auto name = top.string("name");
  if (!name || name->empty()) top.fail("name", "missing; every level needs a name (a string)");
  def.name = *name;
  def.description = top.string("description").value_or("");
  def.author = top.string("author").value_or("");
  def.version = top.string("version").value_or(def.version);
  def.difficulty = readInteger(top, "difficulty", 1, 5).value_or(def.difficulty);
}

void readParams(const LuaTableReader& top, physics::HemisphereParams& params) {
  const auto table = top.table("params");
  if (!table) return;
  rejectUnknownLevelKeys(*table, {"R", "m_s", "m_p", "g"});
  params.radius = table->number("R", params.radius);
  params.shellMass = table->number("m_s", params.shellMass);
  params.pointMass = table->number("m_p", params.pointMass);
  params.gravity = table->number("g", params.gravity);
  // The field is the level's ("params.R"): point at it from the top.
  if (const auto error = physics::paramsError(params, false)) top.fail(error->field, error->message);
}

void readInitial(const LuaTableReader& top, double radius, physics::ForceDrivenState& initial) {
  initial.setZero();
  const auto table = top.table("initial");
  if (!table) return;
  rejectUnknownLevelKeys(*table, {"x_p", "y_p", "xd_p", "yd_p", "w_x", "w_y", "w_z", "u_a", "v_a", "u_o", "v_o", "psi"});
  for (int slot = 0; slot < 12; ++slot) initial[slot] = table->number(physics::kStateNames[slot], 0.0);
  // A start off the face would end every trial on its first tick.
  if (std::hypot(initial[physics::force_slot::x_p], initial[physics::force_slot::y_p]) >= radius)
    table->fail(table->typeOf("x_p") != LUA_TNIL ? "x_p" : "y_p",
                "the mass point must start on the face: |(x_p, y_p)| < R = " + std::to_string(radius) + " m");
}

void readForce(const LuaTableReader& top, physics::CouplingDef& coupling) {
  const auto force = top.table("force");
  if (!force) return;
  rejectUnknownLevelKeys(*force, {"method", "kr", "kv", "alpha"});
  const std::string method = force->string("method").value_or("M3");
  if (method == "M1") coupling.method = physics::ForceMethod::M1;
  else if (method == "M2") coupling.method = physics::ForceMethod::M2;
  else if (method == "M3") coupling.method = physics::ForceMethod::M3;
  else if (method == "visual") coupling.visualOnly = true;  // M3 gains drive the model; nothing is rendered
  else force->fail("method", "unknown method '" + method + "' (expected \"M1\", \"M2\", \"M3\" or \"visual\")");
  coupling.stiffness = force->number("kr", coupling.stiffness);
  coupling.damping = force->number("kv", coupling.damping);
  coupling.alpha = force->number("alpha", coupling.alpha);
  // The field is the force table's ("kr").
  if (const auto error = physics::couplingError(coupling)) force->fail(error->field, error->message);
}

void readMapping(const LuaTableReader& table, DeviceMappingDef& mapping) {
  mapping.scale = readPositive(table, "scale", "scene metres per device metre").value_or(mapping.scale);
  mapping.offset = readVector<3>(table, "offset", "{x, y, z} in metres").value_or(mapping.offset);
}

// device = {scale, offset, per_device = {mouse = {scale, offset}, ...}}: one
// mapping for every device, and overrides per device kind (a desk mouse
// moves centimetres where a PHANToM moves millimetres).
void readDevice(const LuaTableReader& top, LevelDef& def) {
  const auto device = top.table("device");
  if (!device) return;
  rejectUnknownLevelKeys(*device, {"scale", "offset", "per_device"});
  readMapping(*device, def.mapping);
  const auto perDevice = device->table("per_device");
  if (!perDevice) return;
  static_assert(std::size(kMappedDevices) == 4, "per_device's keys are kMappedDevices, each named below");
  rejectUnknownLevelKeys(*perDevice, {kMappedDevices[0], kMappedDevices[1], kMappedDevices[2], kMappedDevices[3]});
  for (const char* name : kMappedDevices) {
    const auto one = perDevice->table(name);
    if (!one) continue;
    rejectUnknownLevelKeys(*one, {"scale", "offset"});
    DeviceMappingDef mapping = def.mapping;
    readMapping(*one, mapping);
    def.deviceMappings[name] = mapping;
  }
}

// A mesh path stays inside the assets directory and names a format assimp reads.
void checkMeshPath(const LuaTableReader& prop, const std::string& mesh) {
  if (mesh.empty()) prop.fail("mesh", "expected a file under assets/, e.g. \"meshes/flag.obj\"");
  if (mesh.front() == '/' || mesh.find("..") != std::string::npos || mesh.find('\\') != std::string::npos)
    prop.fail("mesh", "'" + mesh + "' must be a relative path under assets/ without '..'");
  const std::size_t dot = mesh.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : mesh.substr(dot);
  if (ext != ".obj" && ext != ".gltf" && ext != ".glb")
    prop.fail("mesh", "'" + mesh + "' is not a .obj, .gltf or .glb file");
}

void readProps(const LuaTableReader& scene, std::vector<PropDef>& props) {
  const auto list = scene.table("props");
  if (!list) return;
  const int count = list->entryCount();
  if (static_cast<int>(lua_rawlen(list->state(), list->index())) != count)
    list->fail("", "expected a list of props {mesh = ..., position = ...}, {...}");
  for (int i = 1; i <= count; ++i) {
    const std::string at = positionKey(i);
    if (list->typeAt(i) != LUA_TTABLE) list->fail(at, "expected a prop table {mesh = ..., position = {x, y, z}}");
    lua_rawgeti(list->state(), list->index(), i);
    const LuaTableReader prop(list->state(), -1, list->source(), list->fieldPath(at));
    rejectUnknownLevelKeys(prop, {"mesh", "position", "size", "yaw", "colour"});
    PropDef def;
    def.mesh = prop.string("mesh").value_or("");
    checkMeshPath(prop, def.mesh);
    const auto position = readVector<3>(prop, "position", "{x, y, z} in metres");
    if (!position) prop.fail("position", "required: {x, y, z} in metres, base frame");
    def.position = *position;
    def.size = readPositive(prop, "size", "m").value_or(def.size);
    if (def.size > 1.0) prop.fail("size", "at most 1 m (the radius the mesh is scaled to)");
    def.yaw = prop.number("yaw").value_or(def.yaw);
    if (!std::isfinite(def.yaw)) prop.fail("yaw", "expected a finite angle in radians");
    def.colour = readVector<3>(prop, "colour", "{r, g, b}, each in [0, 1]").value_or(def.colour);
    for (double c : def.colour)
      if (c < 0.0 || c > 1.0) prop.fail("colour", "each of {r, g, b} must be in [0, 1]");
    props.push_back(std::move(def));
  }
}

void readExamplePath(const LuaTableReader& scene, std::vector<std::array<double, 2>>& path) {
  const auto list = scene.table("example_path");
  if (!list) return;
  const int count = list->entryCount();
  if (static_cast<int>(lua_rawlen(list->state(), list->index())) != count)
    list->fail("", "expected a list of points {x, y} in metres");
  if (count > SceneDef::kMaxExamplePath)
    list->fail("", "at most " + std::to_string(SceneDef::kMaxExamplePath) + " points (" + std::to_string(count) +
                       " given)");
  for (int i = 1; i <= count; ++i) {
    const std::string at = positionKey(i);
    if (list->typeAt(i) != LUA_TTABLE) list->fail(at, "expected a point {x, y} in metres");
    lua_rawgeti(list->state(), list->index(), i);
    const LuaTableReader point(list->state(), -1, list->source(), list->fieldPath(at));
    const int n = static_cast<int>(lua_rawlen(point.state(), point.index()));
    std::array<double, 2> p{};
    bool ok = n == 2 && point.entryCount() == 2;
    for (int k = 0; ok && k < 2; ++k) {
      lua_rawgeti(point.state(), point.index(), k + 1);
      ok = lua_type(point.state(), -1) == LUA_TNUMBER;
      if (ok) p[static_cast<std::size_t>(k)] = lua_tonumber(point.state(), -1);
      lua_pop(point.state(), 1);
      ok = ok && std::isfinite(p[static_cast<std::size_t>(k)]);
    }
    lua_pop(list->state(), 1);
    if (!ok) list->fail(at, "expected a point {x, y}: two finite numbers in metres");
    path.push_back(p);
  }
}

void readScene(const LuaTableReader& top, SceneDef& scene) {
  const auto table = top.table("scene");
  if (!table) return;
  rejectUnknownLevelKeys(*table, {"contact_trace", "plots", "record_rate", "props", "example_path"});
  readProps(*table, scene.props);
  readExamplePath(*table, scene.examplePath);
  scene.contactTrace = readBool(*table, "contact_trace").value_or(scene.contactTrace);
  scene.recordRate = readPositive(*table, "record_rate", "Hz").value_or(scene.recordRate);
  if (scene.recordRate > 1000.0) table->fail("record_rate", "at most 1000 Hz (the servo rate)");
  // Slower would be a row every few minutes; 1e-300 overflowed the ticks per row.
  if (scene.recordRate < 0.1) table->fail("record_rate", "at least 0.1 Hz");
  if (const auto plots = table->table("plots")) {
    const int count = plots->entryCount();
    for (int i = 1; i <= count; ++i) {
      const std::string at = positionKey(i);
      lua_rawgeti(plots->state(), plots->index(), i);
      const char* channel = lua_type(plots->state(), -1) == LUA_TSTRING ? lua_tostring(plots->state(), -1) : nullptr;
      const std::string name = channel != nullptr ? channel : "";
      lua_pop(plots->state(), 1);
      if (channel == nullptr) plots->fail(at, "expected a channel name (a string); plots is a list");
      if (std::none_of(kPlotChannels.begin(), kPlotChannels.end(), [&](const char* c) { return name == c; })) {
        const char* near = nearestName(name, kPlotChannels);
        plots->fail(at, "unknown channel '" + name + "'" + (near ? " (did you mean '" + std::string(near) + "'?)" : ""));
      }
      scene.plots.push_back(name);
    }
  }
}

void requireFunction(const LuaTableReader& table, const char* key, bool& present) {
  const int type = table.typeOf(key);
  present = type == LUA_TFUNCTION;
  if (type != LUA_TNIL && type != LUA_TFUNCTION) {
    table.pushField(key);
    const std::string got = describeLuaValue(table.state(), -1);
    lua_pop(table.state(), 1);
    table.fail(key, "expected a function, got " + got);
  }
}

void readCallbacks(const LuaTableReader& top, CallbackDef& callbacks) {
  const auto table = top.table("callbacks");
  if (!table) return;
  rejectUnknownLevelKeys(*table, {"rate", "on_start", "on_update", "on_success", "on_fail"});
  callbacks.rate = table->number("rate", callbacks.rate);
  if (callbacks.rate < 10.0 || callbacks.rate > 100.0) table->fail("rate", "must be from 10 to 100 (Hz)");
  requireFunction(*table, "on_start", callbacks.onStart);
  requireFunction(*table, "on_update", callbacks.onUpdate);
  requireFunction(*table, "on_success", callbacks.onSuccess);
  requireFunction(*table, "on_fail", callbacks.onFail);
}

void readScoring(const LuaTableReader& top, ScoringDef& scoring) {
  requireFunction(top, "score", scoring.hasScoreFunction);
  const auto medals = top.table("medals");
  if (!medals) return;
  if (!scoring.hasScoreFunction) top.fail("medals", "needs a score function (score = function(summary) ... end)");
  rejectUnknownLevelKeys(*medals, {"bronze", "silver", "gold"});
  double* slots[3] = {&scoring.bronze, &scoring.silver, &scoring.gold};
  const char* names[3] = {"bronze", "silver", "gold"};
  for (int i = 0; i < 3; ++i) {
    const auto v = medals->number(names[i]);
    if (!v) medals->fail(names[i], "missing; medals need bronze, silver and gold thresholds (score >= threshold)");
    *slots[i] = *v;
  }
  if (!(scoring.bronze <= scoring.silver && scoring.silver <= scoring.gold))
    medals->fail("silver", "thresholds must satisfy bronze <= silver <= gold");
  scoring.hasMedals = true;
}

LevelDef readLevel(const LuaTableReader& top) {
  rejectUnknownLevelKeys(top, {"name", "description", "author", "difficulty", "version", "params", "initial",
                               "force", "device", "task", "score", "medals", "scene", "callbacks", "demo_bot"});
  LevelDef def;
  def.source = top.source();
  readMeta(top, def);
  readParams(top, def.params);
  readInitial(top, def.params.radius, def.initial);
  readForce(top, def.coupling);
  readDevice(top, def);
  readLevelTask(top, def.task);
  readScoring(top, def.scoring);
  readScene(top, def.scene);
  readCallbacks(top, def.callbacks);
  if (const auto bot = top.string("demo_bot")) {
    std::string why;
    if (!validModuleName(*bot, why)) top.fail("demo_bot", "bad module name '" + *bot + "': " + why);
    def.demoBot = *bot;
  }
  return def;
}

// The sandbox a level runs in has require (modules under scriptsDir), the
// seeded hemiroll.random and the level API.
DataFileLoader levelFileLoader(const LevelLoadOptions& options, const std::string& scriptsDir) {
  return DataFileLoader(kLevelFile, options.limits, [&options, scriptsDir](LuaSandbox& sandbox) {
    installRequire(sandbox, scriptsDir);
    installRandom(sandbox, options.seed);
    LevelScript::installApi(sandbox);
  });
}

LoadedLevel readLoadedLevel(const DataTable& data, const LevelLoadOptions& options) {
  LoadedLevel out;
  out.def = readLevel(data.top);
  if (options.adjust) options.adjust(out.def);
  lua_settop(data.top.state(), data.top.index());  // just the level table, for the script
  out.script = std::make_shared<LevelScript>(data.sandbox, out.def);
  return out;
}

}  // namespace

LoadedLevel LevelLoader::loadFile(const std::string& path) const {
  const std::string scriptsDir = options_.scriptsDir.empty() ? defaultScriptsDir(path) : options_.scriptsDir;
  return levelFileLoader(options_, scriptsDir).loadFile(path, [this](const DataTable& data) {
    return readLoadedLevel(data, options_);
  });
}

LoadedLevel LevelLoader::loadSource(std::string_view source, const std::string& name) const {
  return levelFileLoader(options_, options_.scriptsDir).loadSource(source, name, [this](const DataTable& data) {
    return readLoadedLevel(data, options_);
  });
}

}  // namespace hemiroll::script
