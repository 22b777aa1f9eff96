#include "engine/script/LuaProxyTrajectory.h"

#include <cmath>
#include <cstdio>
#include <lua.hpp>

#include "engine/script/LuaTableReader.h"
#include "engine/script/ScriptError.h"

namespace hemiroll::script {

namespace {

constexpr const char* kReturnNames[6] = {"x", "y", "z", "vx", "vy", "vz"};

std::string formatTime(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", t);
  return text;
}

}  // namespace

LuaProxyTrajectory::LuaProxyTrajectory(std::shared_ptr<LuaSandbox> sandbox, std::string fieldPath)
    : sandbox_(std::move(sandbox)), fieldPath_(std::move(fieldPath)) {
  lua_State* L = sandbox_->state();
  if (lua_type(L, -1) != LUA_TFUNCTION) throw ScriptError(fieldPath_ + ": expected a function");
  lua_checkstack(L, 1);
  lua_pushvalue(L, -1);
  lua_Debug ar;
  lua_getinfo(L, ">S", &ar);  // pops the copy
  definedAt_ = std::string(ar.short_src) + ":" + std::to_string(ar.linedefined);
  functionRef_ = luaL_ref(L, LUA_REGISTRYINDEX);  // pops the function
}

LuaProxyTrajectory::~LuaProxyTrajectory() { luaL_unref(sandbox_->state(), LUA_REGISTRYINDEX, functionRef_); }

physics::ProxyPose LuaProxyTrajectory::at(double t) const {
  lua_State* L = sandbox_->state();
  const int base = lua_gettop(L);
  const std::string call = fieldPath_ + "(t = " + formatTime(t) + ")";
  lua_checkstack(L, 2);
  lua_rawgeti(L, LUA_REGISTRYINDEX, functionRef_);
  lua_pushnumber(L, t);
  int count = 0;
  try {
    count = sandbox_->call(1, LUA_MULTRET, definedAt_);
  } catch (const ScriptError& e) {
    throw ScriptError(std::string(e.what()) + " (in " + call + ")");
  }

  double values[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  std::string problem;
  if (count != 3 && count != 6) {
    problem = "returned " + std::to_string(count) + " value" + (count == 1 ? "" : "s") +
              "; expected x, y, z or x, y, z, vx, vy, vz (m, m/s, base frame)";
  } else {
    for (int i = 0; i < count && problem.empty(); ++i) {
      const int slot = base + 1 + i;
      if (lua_type(L, slot) == LUA_TNUMBER && std::isfinite(lua_tonumber(L, slot)))
        values[i] = lua_tonumber(L, slot);
      else
        problem = "returned " + describeLuaValue(L, slot) + " as value " + std::to_string(i + 1) + " (" +
                  kReturnNames[i] + "); expected a finite number";
    }
  }
  lua_settop(L, base);
  if (!problem.empty()) throw ScriptError(definedAt_ + ": " + call + " " + problem);

  physics::ProxyPose pose;
  pose.position = physics::Vec3(values[0], values[1], values[2]);
  pose.velocity = physics::Vec3(values[3], values[4], values[5]);
  return pose;
}

}  // namespace hemiroll::script
