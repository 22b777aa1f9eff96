#include "engine/script/LuaProxyTrajectory.h"

#include <lua.hpp>

#include "engine/script/PoseReturn.h"
#include "engine/script/ScriptError.h"

namespace hemiroll::script {

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
  const std::string call = fieldPath_ + "(t = " + formatCallTime(t) + ")";
  lua_checkstack(L, 2);
  lua_rawgeti(L, LUA_REGISTRYINDEX, functionRef_);
  lua_pushnumber(L, t);
  int count = 0;
  try {
    count = sandbox_->call(1, LUA_MULTRET, definedAt_);
  } catch (const ScriptError& e) {
    throw ScriptError(std::string(e.what()) + " (in " + call + ")");
  }
  PoseReturn values;
  const std::string problem = readPoseReturn(L, base, count, "base frame", values);
  lua_settop(L, base);
  if (!problem.empty()) throw ScriptError(definedAt_ + ": " + call + " " + problem);

  physics::ProxyPose pose;
  pose.position = physics::Vec3(values.values[0], values.values[1], values.values[2]);
  pose.velocity = physics::Vec3(values.values[3], values.values[4], values.values[5]);
  return pose;
}

}  // namespace hemiroll::script
