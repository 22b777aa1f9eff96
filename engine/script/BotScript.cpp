#include "engine/script/BotScript.h"

#include <filesystem>
#include <lua.hpp>

#include "engine/physics/StateLayout.h"
#include "engine/script/LuaTableReader.h"
#include "engine/script/PoseReturn.h"
#include "engine/script/ScriptModules.h"
#include "engine/script/ScriptError.h"

namespace hemiroll::script {

// What the views' __index reads: the observation of the call in progress
// and the registry references of the nested views.
struct ObservationViews {
  const BotObservation* current = nullptr;  // set only while act runs
  int nested[13] = {};                       // state, target, tolerance, then the ten vectors
};

namespace {

constexpr int kVectorCount = 10;
constexpr int kNestedCount = 3 + kVectorCount;  // state, target, tolerance, then the vectors
constexpr const char* kVectorNames[kVectorCount] = {"mass",   "mass_velocity", "centre", "face_x", "face_y",
                                                    "normal", "contact",       "proxy",  "force",  "device_force"};

// Field codes (the `codes` table maps each name to one). A view of kind k
// answers only the codes that belong to it; anything else reads as nil.
enum Code : int {
  kTime = 1, kProxyDistance, kEngaged, kHeld, kStage, kTimeLimit, kHoldTime, kForceShare,
  kNested0 = 20,     // + 0..12: state, target, tolerance, mass, ..., force, device_force
  kSlot0 = 100,      // + state slot 0..11
  kComponent0 = 200  // + 0..2: x, y, z
};
enum ViewKind : int { kObs = 0, kState = 1, kTarget = 2, kTolerance = 3, kVector0 = 4 };

const Triple3& vectorOf(const BotObservation& o, int i) {
  const Triple3* vectors[kVectorCount] = {&o.mass,   &o.massVelocity, &o.centre, &o.faceX, &o.faceY,
                                          &o.normal, &o.contact,      &o.proxy,  &o.force, &o.deviceForce};
  return *vectors[i];
}

// __index of every view: (view, key) -> value, read straight from the
// observation in C++. Nothing is stored in Lua per tick, so a tick costs only
// the fields a bot actually reads. Allocates nothing and cannot raise.
// Upvalues: 1 ObservationViews (light userdata), 2 view kind, 3 codes table.
int observationIndex(lua_State* L) {
  const auto* views = static_cast<const ObservationViews*>(lua_touserdata(L, lua_upvalueindex(1)));
  const auto kind = static_cast<int>(lua_tointeger(L, lua_upvalueindex(2)));
  lua_pushvalue(L, 2);
  const int code = lua_rawget(L, lua_upvalueindex(3)) == LUA_TNUMBER ? static_cast<int>(lua_tointeger(L, -1)) : 0;
  lua_pop(L, 1);
  const BotObservation* o = views->current;
  if (o == nullptr || code == 0) {
    lua_pushnil(L);
    return 1;
  }
  if (kind == kObs) {
    switch (code) {
      case kTime: lua_pushnumber(L, o->time); return 1;
      case kProxyDistance: lua_pushnumber(L, o->proxyDistance); return 1;
      case kEngaged: lua_pushboolean(L, o->engaged); return 1;
      case kHeld: lua_pushnumber(L, o->held); return 1;
      case kStage: lua_pushinteger(L, o->stage + 1); return 1;  // Lua counts from 1
      case kTimeLimit: lua_pushnumber(L, o->timeLimit); return 1;
      case kHoldTime: lua_pushnumber(L, o->holdTime); return 1;
      case kForceShare: lua_pushnumber(L, o->forceShare); return 1;
      default:
        if (code >= kNested0 && code < kNested0 + kNestedCount) {
          lua_rawgeti(L, LUA_REGISTRYINDEX, views->nested[code - kNested0]);
          return 1;
        }
    }
  } else if (code >= kSlot0 && code < kSlot0 + 12 && kind <= kTolerance) {
    const auto slot = static_cast<std::size_t>(code - kSlot0);
    if (kind == kState)
      lua_pushnumber(L, o->state[slot]);
    else if (!o->targetSet[slot])
      lua_pushnil(L);
    else
      lua_pushnumber(L, kind == kTarget ? o->target[slot] : o->tolerance[slot]);
    return 1;
  } else if (code >= kComponent0 && code < kComponent0 + 3 && kind >= kVector0) {
    lua_pushnumber(L, vectorOf(*o, kind - kVector0)[static_cast<std::size_t>(code - kComponent0)]);
    return 1;
  }
  lua_pushnil(L);
  return 1;
}

// __newindex of every view. Runs inside a protected call; holds no C++
// objects, because luaL_error does not return.
int refuseWrite(lua_State* L) {
  const char* key = lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : luaL_typename(L, 2);
  return luaL_error(L, "obs is read-only (tried to set '%s')", key);
}

// Pushes an empty table whose reads go to observationIndex for `kind`.
// `codes` is the absolute index of the codes table.
void pushView(lua_State* L, ObservationViews* views, int kind, int codes) {
  lua_newtable(L);  // the view: always empty, so every read reaches __index
  lua_newtable(L);  // its metatable
  lua_pushlightuserdata(L, views);
  lua_pushinteger(L, kind);
  lua_pushvalue(L, codes);
  lua_pushcclosure(L, observationIndex, 3);
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, refuseWrite);
  lua_setfield(L, -2, "__newindex");
  lua_pushboolean(L, 0);
  lua_setfield(L, -2, "__metatable");  // getmetatable(obs) gives false; setmetatable refuses
  lua_setmetatable(L, -2);
}

// A shipped bot lives in scripts/bots/, so its modules are in the directory
// above its own; a bot elsewhere gets a level's rule (<dir>/../scripts).
std::string botScriptsDir(const std::string& path) {
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  if (directory.filename() == "bots") return (directory / "..").string();
  return defaultScriptsDir(path);
}

std::string definitionOf(lua_State* L, int index) {
  lua_Debug ar;
  lua_pushvalue(L, index);
  lua_getinfo(L, ">S", &ar);
  return std::string(ar.short_src) + ":" + std::to_string(ar.linedefined);
}

}  // namespace

BotScript::BotScript(const std::string& path, const BotLoadOptions& options)
    : sandbox_(std::make_shared<LuaSandbox>(options.limits)), views_(std::make_unique<ObservationViews>()), path_(path) {
  lua_State* L = sandbox_->state();
  installRequire(*sandbox_, options.scriptsDir.empty() ? botScriptsDir(path) : options.scriptsDir);
  installRandom(*sandbox_, options.seed);
  sandbox_->runFile(path, 1);
  if (lua_type(L, -1) != LUA_TTABLE) {
    const std::string got = describeLuaValue(L, -1);
    lua_pop(L, 1);
    throw ScriptError(path + ": a bot must return a table {name = ..., act = function(t, obs) ... end}, got " + got);
  }
  const LuaTableReader bot(L, -1, path, "");
  const std::optional<std::string> name = bot.string("name");
  if (!name || name->empty()) bot.fail("name", "missing (a non-empty string)");
  name_ = *name;
  if (bot.typeOf("act") != LUA_TFUNCTION) bot.fail("act", bot.typeOf("act") == LUA_TNIL ? "missing (function(t, obs) returning x, y, z)" : "expected a function");
  const int initType = bot.typeOf("init");
  if (initType != LUA_TNIL && initType != LUA_TFUNCTION) bot.fail("init", "expected a function");

  bot.pushField("act");
  actAt_ = definitionOf(L, -1);
  actRef_ = luaL_ref(L, LUA_REGISTRYINDEX);
  initRef_ = LUA_NOREF;
  if (initType == LUA_TFUNCTION) {
    bot.pushField("init");
    initRef_ = luaL_ref(L, LUA_REGISTRYINDEX);
  }
  lua_pop(L, 1);  // the bot table
  buildObservation();
}

BotScript::~BotScript() {
  lua_State* L = sandbox_->state();
  for (int ref : {actRef_, initRef_, obsRef_, memoryRef_}) luaL_unref(L, LUA_REGISTRYINDEX, ref);
  for (int ref : views_->nested) luaL_unref(L, LUA_REGISTRYINDEX, ref);
}

void BotScript::buildObservation() {
  lua_State* L = sandbox_->state();
  lua_checkstack(L, 10);
  lua_newtable(L);  // codes: field name -> Code
  const int codes = lua_gettop(L);
  auto code = [&](const char* name, int value) {
    lua_pushinteger(L, value);
    lua_setfield(L, codes, name);
  };
  const char* scalars[] = {"time", "proxy_distance", "engaged", "held", "stage", "time_limit", "hold_time", "force_share"};
  for (int i = 0; i < 8; ++i) code(scalars[i], kTime + i);
  const char* nested[kNestedCount] = {"state", "target", "tolerance"};
  for (int i = 0; i < kVectorCount; ++i) nested[3 + i] = kVectorNames[i];
  for (int i = 0; i < kNestedCount; ++i) code(nested[i], kNested0 + i);
  for (int i = 0; i < 12; ++i) code(physics::kStateNames[i], kSlot0 + i);
  code("x", kComponent0);
  code("y", kComponent0 + 1);
  code("z", kComponent0 + 2);

  pushView(L, views_.get(), kObs, codes);
  obsRef_ = luaL_ref(L, LUA_REGISTRYINDEX);
  for (int i = 0; i < kNestedCount; ++i) {
    pushView(L, views_.get(), i < 3 ? kState + i : kVector0 + (i - 3), codes);
    views_->nested[i] = luaL_ref(L, LUA_REGISTRYINDEX);
  }
  lua_pop(L, 1);
}

void BotScript::init(const BotLevelInfo& info, std::int64_t seed) {
  if (initRef_ == LUA_NOREF) return;
  lua_State* L = sandbox_->state();
  lua_checkstack(L, 6);
  lua_rawgeti(L, LUA_REGISTRYINDEX, initRef_);
  const std::string at = definitionOf(L, -1);
  lua_newtable(L);
  auto number = [&](const char* key, double v) {
    lua_pushnumber(L, v);
    lua_setfield(L, -2, key);
  };
  auto text = [&](const char* key, const std::string& v) {
    lua_pushlstring(L, v.data(), v.size());
    lua_setfield(L, -2, key);
  };
  text("name", info.name);
  text("file", info.file);
  number("R", info.params.radius);
  number("m_s", info.params.shellMass);
  number("m_p", info.params.pointMass);
  number("g", info.params.gravity);
  // The one place the method becomes a name: Lua's.
  text("method", info.coupling.visualOnly ? "visual" : physics::forceMethodName(info.coupling.method));
  number("kr", info.coupling.stiffness);
  number("kv", info.coupling.damping);
  number("alpha", info.coupling.alpha);
  number("dt", info.dt);
  number("time_limit", info.timeLimit);
  number("engage_distance", info.engageDistance);
  lua_newtable(L);
  number("radius", info.workspaceRadius);
  number("x", info.workspaceCentre[0]);
  number("y", info.workspaceCentre[1]);
  number("z", info.workspaceCentre[2]);
  lua_setfield(L, -2, "workspace");
  if (info.place.inSession) {  // the trial's place in a research session (PROTOCOLS.md)
    const TrialPlace& p = info.place;
    lua_newtable(L);
    auto integer = [&](const char* key, int v) {
      lua_pushinteger(L, v);
      lua_setfield(L, -2, key);
    };
    integer("index", p.trialIndex);
    integer("block", p.block);
    text("block_name", p.blockName);
    integer("trial_in_block", p.trialInBlock);
    integer("condition", p.condition);
    text("condition_label", p.conditionLabel);
    text("group", p.group);
    text("guidance", p.guidance);
    number("guidance_fade", p.guidanceFade);
    lua_setfield(L, -2, "trial");
  }
  if (info.memory != nullptr) {  // the participant's memory, a plain table the bot may change
    memory_ = info.memory;
    lua_newtable(L);
    for (const auto& [key, value] : info.memory->entries()) number(key.c_str(), value);
    lua_pushvalue(L, -1);
    luaL_unref(L, LUA_REGISTRYINDEX, memoryRef_);
    memoryRef_ = luaL_ref(L, LUA_REGISTRYINDEX);
    lua_setfield(L, -2, "memory");
  }
  lua_pushinteger(L, static_cast<lua_Integer>(seed));
  sandbox_->call(2, 0, at);
}

void BotScript::endTrial() {
  if (memory_ == nullptr || memoryRef_ == LUA_NOREF) return;
  lua_State* L = sandbox_->state();
  const int base = lua_gettop(L);
  lua_checkstack(L, 4);
  lua_rawgeti(L, LUA_REGISTRYINDEX, memoryRef_);
  BotMemory kept;
  std::string problem;
  lua_pushnil(L);
  while (problem.empty() && lua_next(L, -2) != 0) {
    // Raw reads only: no metamethod of the bot's runs here.
    if (lua_type(L, -2) != LUA_TSTRING || lua_type(L, -1) != LUA_TNUMBER) {
      problem = "bot memory: level.memory holds " + describeLuaValue(L, -2) + " = " + describeLuaValue(L, -1) +
                "; it keeps name = number entries only";
    } else {
      try {
        kept.set(lua_tostring(L, -2), lua_tonumber(L, -1));
      } catch (const ScriptError& e) {
        problem = e.what();
      }
    }
    lua_pop(L, 1);
  }
  lua_settop(L, base);  // an early stop leaves the key on the stack
  if (!problem.empty()) throw ScriptError(path_ + ": " + problem);
  *memory_ = kept;
}

void BotScript::setTiming(const TrialTiming& timing) { sandbox_->setTiming(timing); }

BotAction BotScript::act(const BotObservation& obs) {
  lua_State* L = sandbox_->state();
  const int base = lua_gettop(L);
  lua_checkstack(L, 8);
  lua_rawgeti(L, LUA_REGISTRYINDEX, actRef_);
  lua_pushnumber(L, obs.time);
  lua_rawgeti(L, LUA_REGISTRYINDEX, obsRef_);
  views_->current = &obs;
  int count = 0;
  try {
    sandbox_->advanceRun(obs.time);
    count = sandbox_->callPerTick(2, LUA_MULTRET, actAt_);
  } catch (const ScriptError& e) {
    views_->current = nullptr;
    throw ScriptError(std::string(e.what()) + " (in act, t = " + formatCallTime(obs.time) + ")");
  }
  views_->current = nullptr;

  PoseReturn values;
  const std::string problem = readPoseReturn(L, base, count, "scene frame", values);
  lua_settop(L, base);
  if (!problem.empty()) throw ScriptError(actAt_ + ": act(t = " + formatCallTime(obs.time) + ") " + problem);
  BotAction action;
  const auto& v = values.values;
  action.position = {v[0], v[1], v[2]};
  action.velocity = {v[3], v[4], v[5]};
  action.hasVelocity = values.count == 6;
  return action;
}

}  // namespace hemiroll::script
