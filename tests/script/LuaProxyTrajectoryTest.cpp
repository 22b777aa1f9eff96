// engine/script/LuaProxyTrajectory: a proxy written in Lua, evaluated like
// any ProxyTrajectory; failures become positioned ScriptErrors.

#include "engine/script/LuaProxyTrajectory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <lua.hpp>
#include <memory>

#include "engine/script/ScriptError.h"
#include "tests/support/ErrorMessage.h"

namespace hemiroll::script {
namespace {

using ::testing::HasSubstr;

std::unique_ptr<LuaProxyTrajectory> proxyFrom(const std::string& source, const SandboxLimits& limits = {}) {
  auto sandbox = std::make_shared<LuaSandbox>(limits);
  sandbox->runChunk(source, "p.lua", 1);
  return std::make_unique<LuaProxyTrajectory>(sandbox, "drive.proxy");
}

std::string errorAt(const physics::ProxyTrajectory& proxy, double t) {
  return test::messageOf<ScriptError>([&] { proxy.at(t); });
}

TEST(LuaProxyTrajectory, ReturnsPositionAndVelocity) {
  const auto proxy = proxyFrom("return function(t) return t, 2 * t, 0.04, 1, 2, 0 end");
  const physics::ProxyPose pose = proxy->at(0.5);
  EXPECT_EQ(pose.position, physics::Vec3(0.5, 1.0, 0.04));
  EXPECT_EQ(pose.velocity, physics::Vec3(1.0, 2.0, 0.0));
  EXPECT_EQ(proxy->definedAt(), "p.lua:1");
}

TEST(LuaProxyTrajectory, ThreeValuesMeanZeroVelocity) {
  const auto proxy = proxyFrom("return function(t) return 0.01, 0, 0.04 end");
  EXPECT_EQ(proxy->at(3.0).velocity, physics::Vec3::Zero());
}

TEST(LuaProxyTrajectory, NonNumbersNameTheValueAndTheDefinition) {
  const auto proxy = proxyFrom("\nreturn function(t)\n  return 0, 'y', 0\nend");
  EXPECT_EQ(errorAt(*proxy, 0.25),
            "p.lua:2: drive.proxy(t = 0.25) returned string as value 2 (y); expected a finite number");
}

TEST(LuaProxyTrajectory, NonFiniteAndWrongCountsAreRefused) {
  EXPECT_THAT(errorAt(*proxyFrom("return function(t) return 0, 0, 1/0 end"), 0),
              HasSubstr("returned inf as value 3 (z)"));
  EXPECT_THAT(errorAt(*proxyFrom("return function(t) return 0, 0 end"), 0), HasSubstr("returned 2 values"));
  EXPECT_THAT(errorAt(*proxyFrom("return function(t) end"), 0), HasSubstr("returned 0 values"));
  EXPECT_THAT(errorAt(*proxyFrom("return function(t) return 1, 2, 3, 4 end"), 0), HasSubstr("returned 4 values"));
}

TEST(LuaProxyTrajectory, RuntimeErrorsCarryLineAndTime) {
  const auto proxy = proxyFrom("return function(t)\n  if t > 1 then error('lost the hand') end\n  return 0, 0, 0 end");
  EXPECT_NO_THROW(proxy->at(0.5));
  const std::string message = errorAt(*proxy, 1.5);
  EXPECT_THAT(message, HasSubstr("p.lua:2: lost the hand"));
  EXPECT_THAT(message, HasSubstr("drive.proxy(t = 1.5)"));
}

TEST(LuaProxyTrajectory, EachCallHasItsOwnQuota) {
  SandboxLimits limits;
  limits.callInstructionQuota = 20'000;
  const auto proxy = proxyFrom("return function(t) if t > 1 then while true do end end return 0, 0, 0 end", limits);
  for (int i = 0; i < 1000; ++i) ASSERT_NO_THROW(proxy->at(0.001 * i)) << "quota must reset per call";
  EXPECT_THAT(errorAt(*proxy, 2.0), HasSubstr("instruction quota of 20000"));
  EXPECT_NO_THROW(proxy->at(0.0)) << "the state stays usable after a failed call";
}

}  // namespace
}  // namespace hemiroll::script
