// engine/script/ScenarioLoader: scenario files into ScenarioDef, with the
// paper's defaults and one clear message per mistake.

#include "engine/script/ScenarioLoader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "engine/physics/StateLayout.h"
#include "engine/script/ScriptError.h"
#include "tests/support/ErrorMessage.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::script {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

ScenarioDef load(const std::string& source) { return ScenarioLoader().loadSource(source, "s.lua"); }

std::string errorOf(const std::string& source) { return test::messageOf<ScriptError>([&] { load(source); }); }

TEST(ScenarioLoader, MissingParamsAreThePapers) {
  const ScenarioDef def = load("return {drive = {kind = 'free'}}");
  const physics::HemisphereParams paper;
  EXPECT_EQ(def.params.radius, paper.radius);
  EXPECT_EQ(def.params.shellMass, paper.shellMass);
  EXPECT_EQ(def.params.pointMass, paper.pointMass);
  EXPECT_EQ(def.params.gravity, paper.gravity);
  EXPECT_EQ(def.initial, physics::ForceDrivenState::Zero());
  EXPECT_EQ(def.drive.kind, DriveKind::Free);
  EXPECT_FALSE(def.duration.has_value());
  EXPECT_FALSE(def.timeStep.has_value());
  EXPECT_FALSE(def.integrator.has_value());
}

TEST(ScenarioLoader, ReadsEveryField) {
  const ScenarioDef def = load(R"(
    return {
      params = {R = 0.05, m_s = 0.2, m_p = 0.5, g = 9.8},
      initial = {x_p = 0.001, y_p = 0.002, xd_p = 0.003, yd_p = 0.004, w_x = 5, w_y = 6, w_z = 7,
                 u_a = 8, v_a = 9, u_o = 0.1, v_o = 0.2, psi = 12},
      drive = {kind = 'free'},
      duration = 3, dt = 0.002, integrator = 'rk4',
    })");
  EXPECT_EQ(def.params.radius, 0.05);
  EXPECT_EQ(def.params.shellMass, 0.2);
  EXPECT_EQ(def.params.pointMass, 0.5);
  EXPECT_EQ(def.params.gravity, 9.8);
  const double expected[12] = {0.001, 0.002, 0.003, 0.004, 5, 6, 7, 8, 9, 0.1, 0.2, 12};
  for (int i = 0; i < 12; ++i) EXPECT_EQ(def.initial[i], expected[i]) << physics::kStateNames[i];
  EXPECT_EQ(def.duration, 3.0);
  EXPECT_EQ(def.timeStep, 0.002);
  EXPECT_EQ(def.integrator, "rk4");
  EXPECT_EQ(def.source, "s.lua");
}

TEST(ScenarioLoader, RoseDrive) {
  const ScenarioDef def = load("return {drive = {kind = 'rose', r1 = 0.01, r2 = 0.005, k = 4, Omega = -math.pi / 5}}");
  ASSERT_EQ(def.drive.kind, DriveKind::Rose);
  EXPECT_EQ(def.drive.rose.r1, 0.01);
  EXPECT_EQ(def.drive.rose.r2, 0.005);
  EXPECT_EQ(def.drive.rose.k, 4.0);
  EXPECT_EQ(def.drive.rose.omega, -M_PI / 5);
  // Omitted rose fields are the paper's.
  const ScenarioDef paper = load("return {drive = {kind = 'rose'}}");
  const physics::RoseDef rose;
  EXPECT_EQ(paper.drive.rose.r1, rose.r1);
  EXPECT_EQ(paper.drive.rose.omega, rose.omega);
}

TEST(ScenarioLoader, RoseAcceptsABareHemisphere) {
  EXPECT_EQ(load("return {params = {m_p = 0}, drive = {kind = 'rose'}}").params.pointMass, 0.0);
  EXPECT_EQ(errorOf("return {params = {m_p = 0}, drive = {kind = 'free'}}"),
            "s.lua:1: params.m_p: (mass point) must be positive for a force-driven model");
}

TEST(ScenarioLoader, ProxyDriveWithConstantTables) {
  const ScenarioDef positional =
      load("return {drive = {kind = 'proxy', method = 'M2', kr = 100, kv = 1, alpha = 3, proxy = {0.01, 0.02, 0.04}}}");
  ASSERT_EQ(positional.drive.kind, DriveKind::Proxy);
  EXPECT_EQ(positional.drive.coupling.method, physics::ForceMethod::M2);
  EXPECT_EQ(positional.drive.coupling.stiffness, 100.0);
  EXPECT_EQ(positional.drive.coupling.damping, 1.0);
  EXPECT_EQ(positional.drive.coupling.alpha, 3.0);
  EXPECT_EQ(positional.drive.proxy->at(7.0).position, physics::Vec3(0.01, 0.02, 0.04));

  const ScenarioDef named = load("return {drive = {kind = 'proxy', proxy = {x = 0.01, y = 0.02, z = 0.04}}}");
  EXPECT_EQ(named.drive.proxy->at(0.0).position, physics::Vec3(0.01, 0.02, 0.04));
  const physics::CouplingDef paper;
  EXPECT_EQ(named.drive.coupling.method, paper.method);
  EXPECT_EQ(named.drive.coupling.stiffness, paper.stiffness);
}

TEST(ScenarioLoader, ProxyFunctionOutlivesTheLoader) {
  const ScenarioDef def = load(R"(
    local amplitude = 0.003
    return {drive = {kind = 'proxy', method = 'M1',
                     proxy = function(t) return amplitude * t, 0, 0.04, amplitude, 0, 0 end}})");
  const physics::ProxyPose pose = def.drive.proxy->at(2.0);
  EXPECT_EQ(pose.position, physics::Vec3(0.006, 0.0, 0.04));
  EXPECT_EQ(pose.velocity, physics::Vec3(0.003, 0.0, 0.0));
}

TEST(ScenarioLoader, BadProxyReturnsFailAtLoad) {
  EXPECT_THAT(errorOf("return {drive = {kind = 'proxy', proxy = function(t) return 'x' end}}"),
              HasSubstr("s.lua:1: drive.proxy(t = 0) returned 1 value"));
}

// One-line sources: every mistake is on line 1 (MistakesNameTheLineOfTheField
// has them on lines of their own). Each message starts as given; three are
// compared in full.
TEST(ScenarioLoader, MistakesNameTheFieldPath) {
  const std::pair<const char*, const char*> cases[] = {
      {"return {}", "s.lua:1: drive: missing"},
      {"return {drive = {}}", "s.lua:1: drive.kind: missing"},
      {"return {drive = {kind = 'wobble'}}", "s.lua:1: drive.kind: unknown drive kind 'wobble'"},
      {"return {drive = {kind = 'proxy', method = 'M4', proxy = {0, 0, 0}}}",
       "s.lua:1: drive.method: unknown method 'M4'"},
      {"return {drive = {kind = 'proxy', kr = -1, proxy = {0, 0, 0}}}",
       "s.lua:1: drive.kr: (stiffness) must be a finite, non-negative N/m"},
      {"return {drive = {kind = 'proxy'}}", "s.lua:1: drive.proxy: missing"},
      {"return {drive = {kind = 'proxy', proxy = {0, 0}}}", "s.lua:1: drive.proxy: expected"},
      {"return {drive = {kind = 'proxy', proxy = 5}}", "s.lua:1: drive.proxy: expected a function"},
      {"return {drive = {kind = 'free', r1 = 1}}", "s.lua:1: drive: unknown field 'r1'"},
      {"return {drive = {kind = 'free'}, params = {m_s = -0.1}}",
       "s.lua:1: params.m_s: (hemisphere mass) must be a positive finite number"},
      {"return {drive = {kind = 'free'}, params = {R = 0}}",
       "s.lua:1: params.R: (radius) must be a positive finite number"},
      {"return {drive = {kind = 'free'}, params = {mass = 1}}", "s.lua:1: params: unknown field 'mass'"},
      {"return {drive = {kind = 'free'}, initial = {theta = 1}}", "s.lua:1: initial: unknown field 'theta'"},
      {"return {drive = {kind = 'free'}, initial = {0, 0}}", "s.lua:1: initial: unknown fields [1], [2]"},
      {"return {drive = {kind = 'rose'}, initial = {x_p = 0.02}}", "s.lua:1: initial.x_p: the rose drive"},
      {"return {drive = {kind = 'rose', r2 = -0.001}}", "s.lua:1: drive.r2: must be a non-negative length"},
      {"return {drive = {kind = 'free'}, dt = 0}", "s.lua:1: dt: must be a positive"},
      {"return {drive = {kind = 'free'}, duration = -2}", "s.lua:1: duration: must be a positive"},
      {"return {drive = {kind = 'free'}, integrator = 'euler'}",
       "s.lua:1: integrator: unknown integrator 'euler' (available: rk4"},
      {"return {drive = {kind = 'free'}, durration = 1}", "s.lua:1: unknown field 'durration'"},
      {"return {drive = {kind = 'free'}, tol = 0}", "s.lua:1: tol: must be in 1e-15 .. 1"},
      {"return {drive = {kind = 'free'}, tol = 1e-300}", "s.lua:1: tol: must be in 1e-15 .. 1"},
      {"return {drive = {kind = 'free'}, tol = 'tight'}", "s.lua:1: tol: expected a number"},
      {"return {drive = {kind = 'free'}, orientation = 'euler'}",
       "s.lua:1: orientation: must be 'angles' or 'quaternion', got 'euler'"},
      {"return {drive = {kind = 'rose'}, orientation = 'quaternion'}", "s.lua:1: orientation: the rose drive"},
  };
  for (const auto& [source, expected] : cases) EXPECT_THAT(errorOf(source), StartsWith(expected)) << source;
  // These in full.
  EXPECT_EQ(errorOf("return {drive = {kind = 'rose', r1 = 'a'}}"), "s.lua:1: drive.r1: expected a number, got string");
  EXPECT_EQ(errorOf("return 3"), "s.lua:1: the scenario must return a table, got number");
  EXPECT_EQ(errorOf("return {drive = {kind = 'free'}, params = {g = 0/0}}"), "s.lua:1: params.g: expected a finite number, got nan");
}

TEST(ScenarioLoader, MistakesNameTheLineOfTheField) {
  EXPECT_EQ(errorOf("return {\n  drive = {\n    kind = 'rose',\n    r1 = 'a',\n  },\n}"),
            "s.lua:4: drive.r1: expected a number, got string");
  EXPECT_EQ(errorOf("return {\n  drive = {kind = 'free'},\n  params = {\n    m_p = 0,\n  },\n}"),
            "s.lua:4: params.m_p: (mass point) must be positive for a force-driven model");
  EXPECT_EQ(errorOf("return {\n  drive = {\n    kind = 'proxy', proxy = {0, 0, 0},\n    kv = -1,\n  },\n}"),
            "s.lua:4: drive.kv: (damping) must be a finite, non-negative N s/m");
  // An unknown key is the table's mistake: the line of the table.
  EXPECT_EQ(errorOf("return {\n  drive = {kind = 'free'},\n  initial = {\n    theta = 1 },\n}"),
            "s.lua:3: initial: unknown field 'theta' (expected one of: x_p, y_p, xd_p, yd_p, w_x, w_y, w_z, u_a, v_a, "
            "u_o, v_o, psi)");
  EXPECT_EQ(errorOf("\nreturn 3"), "s.lua:2: the scenario must return a table, got number");
}

TEST(ScenarioLoader, ToleranceAndOrientationAreOptional) {
  const ScenarioDef plain = load("return {drive = {kind = 'free'}}");
  EXPECT_FALSE(plain.tolerance.has_value());
  EXPECT_FALSE(plain.orientation.has_value());
  const ScenarioDef set = load("return {drive = {kind = 'free'}, integrator = 'dop853', tol = 1e-10, orientation = 'quaternion'}");
  EXPECT_EQ(set.tolerance, 1e-10);
  EXPECT_EQ(set.orientation, "quaternion");
}

TEST(ScenarioLoader, FilesAreNamedAsGiven) {
  const test::TempDirectory dir;
  const std::string good = dir.write("good.lua", "return {drive = {kind = 'free'}}");
  EXPECT_EQ(ScenarioLoader().loadFile(good).source, good);
  const std::string bad = dir.write("bad.lua", "\n\nreturn {drive = {kind = 'free'}, dt = 'fast'}");
  try {
    ScenarioLoader().loadFile(bad);
    FAIL() << "expected an error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()), bad + ":3: dt: expected a number, got string");
  }
  const std::string missing = (dir.path() / "missing.lua").string();
  EXPECT_EQ(test::messageOf<ScriptError>([&] { ScenarioLoader().loadFile(missing); }), missing + ":1: no such file");
}

TEST(ScenarioLoader, ShebangLineKeepsLineNumbers) {
  const test::TempDirectory dir;
  const std::string path = dir.write("s.lua", "#!/usr/bin/env hemiroll\nlocal x = nil\nreturn x.y\n");
  try {
    ScenarioLoader().loadFile(path);
    FAIL() << "expected an error";
  } catch (const ScriptError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("s.lua:3:"));
  }
}

}  // namespace
}  // namespace hemiroll::script
