#include "engine/script/PoseReturn.h"

#include <cmath>
#include <cstdio>
#include <lua.hpp>

#include "engine/script/LuaTableReader.h"

namespace hemiroll::script {

namespace {

constexpr const char* kReturnNames[6] = {"x", "y", "z", "vx", "vy", "vz"};

}  // namespace

std::string readPoseReturn(lua_State* L, int base, int count, const char* frame, PoseReturn& out) {
  if (count != 3 && count != 6)
    return "returned " + std::to_string(count) + " value" + (count == 1 ? "" : "s") +
           "; expected x, y, z or x, y, z, vx, vy, vz (m, m/s, " + frame + ")";
  PoseReturn pose;
  pose.count = count;
  for (int i = 0; i < count; ++i) {
    const int slot = base + 1 + i;
    if (lua_type(L, slot) != LUA_TNUMBER || !std::isfinite(lua_tonumber(L, slot)))
      return "returned " + describeLuaValue(L, slot) + " as value " + std::to_string(i + 1) + " (" + kReturnNames[i] +
             "); expected a finite number";
    pose.values[static_cast<std::size_t>(i)] = lua_tonumber(L, slot);
  }
  out = pose;
  return "";
}

std::string formatCallTime(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", t);
  return text;
}

}  // namespace hemiroll::script
