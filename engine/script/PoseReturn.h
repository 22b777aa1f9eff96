#pragma once
// What a script function that moves the proxy returns: x, y, z [, vx, vy, vz]
// in metres and metres per second, 3 or 6 finite numbers. A scenario's proxy
// function (LuaProxyTrajectory) and a bot's act (BotScript) both return it;
// one reader checks it, so that both word a wrong return the same way.

#include <array>
#include <string>

struct lua_State;

namespace hemiroll::script {

struct PoseReturn {
  std::array<double, 6> values{};  // x, y, z [m], vx, vy, vz [m/s]; the velocity stays 0 when count is 3
  int count = 0;                   // 3 or 6
};

// Reads the `count` values a call left above stack index `base` (it does not
// pop them). Returns "" and fills `out`, or what is wrong: "returned 2
// values; expected x, y, z or x, y, z, vx, vy, vz (m, m/s, base frame)",
// with `frame` naming the coordinates ("base frame", "scene frame").
std::string readPoseReturn(lua_State* L, int base, int count, const char* frame, PoseReturn& out);

// t as the messages about a call write it ("%.9g": "act(t = 0.02)").
std::string formatCallTime(double t);

}  // namespace hemiroll::script
