#pragma once
// The proxy as a Lua function t -> x, y, z [, vx, vy, vz] (base frame, m and
// m/s), evaluated at every integrator stage. Velocities may be left out
// together (they are then zero). Each evaluation runs under the sandbox's
// per-call instruction quota and memory cap.
//
// at() throws ScriptError when the function fails or returns anything but
// 3 or 6 finite numbers; the message names the file and the line (of the
// error, or of the function's definition for bad return values) and t.
//
// Not thread-safe: every evaluation runs on the one Lua state the scenario
// was loaded into. Use it from one thread (headless runs, tests).

#include <memory>
#include <string>

#include "engine/physics/ForceDrivenSystem.h"
#include "engine/script/LuaSandbox.h"

namespace hemiroll::script {

class LuaProxyTrajectory final : public physics::ProxyTrajectory {
 public:
  // Takes (pops) the function on top of the sandbox's stack. `fieldPath`
  // names it in messages ("drive.proxy").
  LuaProxyTrajectory(std::shared_ptr<LuaSandbox> sandbox, std::string fieldPath);
  ~LuaProxyTrajectory() override;
  LuaProxyTrajectory(const LuaProxyTrajectory&) = delete;
  LuaProxyTrajectory& operator=(const LuaProxyTrajectory&) = delete;

  physics::ProxyPose at(double t) const override;

  // "file:line" where the function is defined.
  const std::string& definedAt() const { return definedAt_; }

 private:
  std::shared_ptr<LuaSandbox> sandbox_;
  int functionRef_ = 0;
  std::string fieldPath_;
  std::string definedAt_;
};

}  // namespace hemiroll::script
