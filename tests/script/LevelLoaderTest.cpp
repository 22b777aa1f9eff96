// engine/script/LevelLoader: level files into LevelDef + LevelScript, with
// the paper's defaults and one "file:line: what" message per mistake.

#include "engine/script/LevelLoader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "engine/script/ScriptError.h"
#include "tests/support/ErrorMessage.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::script {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

LoadedLevel load(const std::string& source) { return LevelLoader().loadSource(source, "lv.lua"); }

std::string errorOf(const std::string& source) { return test::messageOf<ScriptError>([&] { load(source); }); }

const char* kMinimal = "return { name = 'x' }";

// Caps before work (issue 19): a time limit whose tick count overflows,
// and stage or zone lists that make every tick slow, are refused by name.
TEST(LevelLoader, TimeLimitStagesAndZonesHaveCaps) {
  EXPECT_THAT(errorOf("return { name = 'x', task = { targets = { x_p = { value = 0, tol = 1 } }, time_limit = 2e16 } }"),
              HasSubstr("task.time_limit: must be at most 86400 s (a day)"));
  EXPECT_THAT(errorOf("local z = {} for i = 1, 101 do z[i] = { shape = 'circle', centre = {1, 1}, radius = 0.01 } end\n"
                      "return { name = 'x', task = { targets = { x_p = { value = 0, tol = 1 } }, forbidden = z } }"),
              HasSubstr("task.forbidden: 101 zones; a level may have at most 100"));
  EXPECT_THAT(errorOf("local st = {} for i = 1, 101 do st[i] = { targets = { x_p = { value = 0, tol = 1 } } } end\n"
                      "return { name = 'x', task = { stages = st } }"),
              HasSubstr("task.stages: 101 stages; a level may have at most 100"));
  EXPECT_THAT(errorOf("return { name = 'x', scene = { record_rate = 1e-300 } }"),
              HasSubstr("scene.record_rate: at least 0.1 Hz"));
  // At the caps, they load.
  EXPECT_NO_THROW(load("return { name = 'x', task = { targets = { x_p = { value = 0, tol = 1 } }, time_limit = 86400 } }"));
}

TEST(LevelLoader, MinimalLevelHasThePapersDefaults) {
  const LevelDef def = load(kMinimal).def;
  const physics::HemisphereParams paper;
  const physics::CouplingDef paperCoupling;
  EXPECT_EQ(def.name, "x");
  EXPECT_EQ(def.params.radius, paper.radius);
  EXPECT_EQ(def.params.pointMass, paper.pointMass);
  EXPECT_EQ(def.initial, physics::ForceDrivenState::Zero());
  EXPECT_EQ(def.coupling.method, physics::ForceMethod::M3);
  EXPECT_EQ(def.coupling.stiffness, paperCoupling.stiffness);
  EXPECT_EQ(def.coupling.alpha, paperCoupling.alpha);
  EXPECT_FALSE(def.coupling.visualOnly);
  EXPECT_EQ(def.task.timeLimit, 240.0);
  EXPECT_TRUE(def.task.watchOnly());
  EXPECT_TRUE(def.task.failure.tipOver);
  EXPECT_FALSE(def.scoring.hasScoreFunction);
  EXPECT_EQ(def.mapping.scale, 1.0);
  EXPECT_EQ(def.difficulty, 1);
}

TEST(LevelLoader, ReadsEveryField) {
  const LoadedLevel level = load(R"(
    return {
      name = "all", description = "d", author = "a", difficulty = 3, version = "2.1",
      params = {R = 0.05, m_s = 0.2, m_p = 0.5, g = 9.8},
      initial = {x_p = 0.001, psi = 0.5},
      force = {method = "M2", kr = 100, kv = 5, alpha = 1.5},
      device = {scale = 0.5, offset = {0.01, 0.02, 0.03}},
      task = {
        targets = {u_ca = {value = {-0.04, -0.04}, tol = 0.004}, omega = {value = {0, 0, 0}, tol = {0.01, 0.02, 0.03}},
                   psi = {value = 1, tol = 0.1}},
        hold = 0.5, time_limit = 60,
        fail = {tip_over = false, off_face = true, area = {shape = "circle", center = {0, 0}, radius = 0.3}},
        forbidden = {{name = "pit", shape = "box", min = {0.01, 0.01}, max = {0.02, 0.03}}},
      },
      score = function(s) return 1 end,
      medals = {bronze = 1, silver = 2, gold = 3},
      scene = {contact_trace = false, plots = {"u_a", "energy"}, record_rate = 50,
               props = {{mesh = "meshes/flag.obj", position = {0.1, -0.2, 0}, size = 0.02, yaw = 0.5,
                         colour = {1, 0.5, 0}}, {mesh = "meshes/cone.gltf", position = {0, 0, 0}}},
               example_path = {{0, 0}, {0.005, 0.001}, {0.01, -0.002}}},
      callbacks = {rate = 25, on_update = function(s) end},
      demo_bot = "bots.rose",
    })");
  const LevelDef& d = level.def;
  EXPECT_EQ(d.description, "d");
  EXPECT_EQ(d.author, "a");
  EXPECT_EQ(d.difficulty, 3);
  EXPECT_EQ(d.version, "2.1");
  EXPECT_EQ(d.params.radius, 0.05);
  EXPECT_EQ(d.initial[physics::force_slot::x_p], 0.001);
  EXPECT_EQ(d.initial[physics::force_slot::psi], 0.5);
  EXPECT_EQ(d.coupling.method, physics::ForceMethod::M2);
  EXPECT_EQ(d.coupling.stiffness, 100.0);
  EXPECT_EQ(d.mapping.scale, 0.5);
  EXPECT_EQ(d.mapping.offset[2], 0.03);
  ASSERT_EQ(d.task.stages.size(), 1u);
  const auto& targets = d.task.stages[0].targets;
  ASSERT_EQ(targets.size(), 6u);  // w_x w_y w_z u_a v_a psi, in slot order
  EXPECT_EQ(targets[0].variable, TaskVariable::w_x);
  EXPECT_EQ(targets[2].tolerance, 0.03);
  EXPECT_EQ(targets[3].variable, TaskVariable::u_a);
  EXPECT_EQ(targets[3].value, -0.04);
  EXPECT_EQ(targets[4].tolerance, 0.004);
  EXPECT_EQ(targets[5].variable, TaskVariable::psi);
  EXPECT_EQ(d.task.stages[0].hold, 0.5);
  EXPECT_EQ(d.task.timeLimit, 60.0);
  EXPECT_FALSE(d.task.failure.tipOver);
  ASSERT_TRUE(d.task.failure.area.has_value());
  EXPECT_EQ(d.task.failure.area->radius, 0.3);
  ASSERT_EQ(d.task.forbidden.size(), 1u);
  EXPECT_EQ(d.task.forbidden[0].shape, ZoneShape::Box);
  EXPECT_EQ(d.task.forbidden[0].max[1], 0.03);
  EXPECT_TRUE(d.scoring.hasScoreFunction);
  EXPECT_EQ(d.scoring.gold, 3.0);
  EXPECT_FALSE(d.scene.contactTrace);
  EXPECT_EQ(d.scene.plots, (std::vector<std::string>{"u_a", "energy"}));
  EXPECT_EQ(d.scene.recordRate, 50.0);
  ASSERT_EQ(d.scene.props.size(), 2u);
  EXPECT_EQ(d.scene.props[0].mesh, "meshes/flag.obj");
  EXPECT_EQ(d.scene.props[0].position, (std::array<double, 3>{0.1, -0.2, 0.0}));
  EXPECT_EQ(d.scene.props[0].size, 0.02);
  EXPECT_EQ(d.scene.props[0].yaw, 0.5);
  EXPECT_EQ(d.scene.props[0].colour, (std::array<double, 3>{1.0, 0.5, 0.0}));
  EXPECT_EQ(d.scene.props[1].size, PropDef{}.size);  // defaults
  EXPECT_EQ(d.scene.props[1].colour, PropDef{}.colour);
  ASSERT_EQ(d.scene.examplePath.size(), 3u);
  EXPECT_EQ(d.scene.examplePath[2], (std::array<double, 2>{0.01, -0.002}));
  EXPECT_EQ(d.callbacks.rate, 25.0);
  EXPECT_TRUE(d.callbacks.onUpdate);
  EXPECT_FALSE(d.callbacks.onStart);
  EXPECT_EQ(d.demoBot, "bots.rose");
  EXPECT_NE(level.script, nullptr);
}

TEST(LevelLoader, DeviceMappingPerDeviceKindInheritsTheRest) {
  const LevelDef def = load(R"(return { name = 'x',
      device = { scale = 0.5, offset = {0.01, 0.02, 0.03},
                 per_device = { mouse = { scale = 0.2 }, udp = { offset = {0, 0, 0.05} } } } })")
                           .def;
  EXPECT_EQ(def.mappingFor("mouse").scale, 0.2);
  EXPECT_EQ(def.mappingFor("mouse").offset[1], 0.02);  // inherited
  EXPECT_EQ(def.mappingFor("udp").scale, 0.5);         // inherited
  EXPECT_EQ(def.mappingFor("udp").offset[2], 0.05);
  EXPECT_EQ(def.mappingFor("bot").scale, 0.5);         // no override: the level's
  EXPECT_EQ(def.mappingFor("joystick").offset[0], 0.01);
  EXPECT_THAT(errorOf("return { name = 'x', device = { per_device = { trackball = {} } } }"),
              HasSubstr("lv.lua:1: device.per_device.trackball: unknown key"));
  EXPECT_THAT(errorOf("return { name = 'x', device = { per_device = { mouse = { scale = -1 } } } }"),
              HasSubstr("device.per_device.mouse.scale"));
}

TEST(LevelLoader, VisualMethodKeepsM3GainsAndRendersNothing) {
  const LevelDef d = load("return {name = 'v', force = {method = 'visual'}}").def;
  EXPECT_TRUE(d.coupling.visualOnly);
  EXPECT_EQ(d.coupling.method, physics::ForceMethod::M3);
}

TEST(LevelLoader, StagesCarryTheirOwnHoldOrTheTasks) {
  const LevelDef d = load(R"(
    return { name = 's', task = { hold = 2, stages = {
      { name = "a", targets = { p = {value = {0, 0}, tol = 0.01} } },
      { targets = { x_p = {value = 0.01, tol = 0.001} }, hold = 0 },
    } } })").def;
  ASSERT_EQ(d.task.stages.size(), 2u);
  EXPECT_EQ(d.task.stages[0].name, "a");
  EXPECT_EQ(d.task.stages[0].hold, 2.0);
  EXPECT_EQ(d.task.stages[1].hold, 0.0);
  EXPECT_EQ(d.task.stages[1].targets[0].value, 0.01);
}

// Every error class names the file and the line of the offending field.
struct ErrorCase {
  const char* source;
  const char* expected;  // the complete "lv.lua:LINE: ..." start
};

class LevelLoaderErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(LevelLoaderErrors, NameFileLineAndWhat) {
  const std::string message = errorOf(GetParam().source);
  EXPECT_THAT(message, StartsWith(GetParam().expected)) << GetParam().source;
}

INSTANTIATE_TEST_SUITE_P(
    Classes, LevelLoaderErrors,
    ::testing::Values(
        ErrorCase{"return {\n name = 'x',\n bogus = 1 }", "lv.lua:3: bogus: unknown key 'bogus'"},
        ErrorCase{"return {\n name = 'x',\n task = {\n  hold = 1,\n  tragets = {} } }",
                  "lv.lua:5: task.tragets: unknown key 'tragets' (did you mean 'targets'?)"},
        ErrorCase{"return {\n name = 'x',\n params = {\n  R = 'big' } }", "lv.lua:4: params.R: expected a number, got string"},
        ErrorCase{"return {\n name = 'x',\n params = {\n  R = -1 } }", "lv.lua:4: params.R: (radius) must be"},
        ErrorCase{"return {\n name = 'x',\n params = {\n  m_p = 0/0 } }", "lv.lua:4: params.m_p: expected a finite number, got nan"},
        ErrorCase{"return {\n description = 'no name' }", "lv.lua:1: name: missing"},
        ErrorCase{"return { name = 'x', initial = {\n y_p = 0.05 } }", "lv.lua:2: initial.y_p: the mass point must start on the face"},
        ErrorCase{"return {\n name = 'x',\n difficulty = 7 }", "lv.lua:3: difficulty: expected a whole number from 1 to 5"},
        ErrorCase{"return {\n name = 'x',\n force = {\n  method = 'M4' } }", "lv.lua:4: force.method: unknown method 'M4'"},
        ErrorCase{"return {\n name = 'x',\n force = {\n  kr = -5 } }", "lv.lua:4: force.kr: (stiffness) must be"},
        ErrorCase{"return { name = 'x', task = {\n targets = {\n  u_ca = {value = {1}, tol = 0.1} } } }",
                  "lv.lua:3: task.targets.u_ca.value: expected a list of 2 numbers for u_ca (1 entries given)"},
        ErrorCase{"return { name = 'x', task = {\n targets = {\n  x_p = {value = 0, tol = 0} } } }",
                  "lv.lua:3: task.targets.x_p.tol: every tolerance must be > 0"},
        ErrorCase{"return { name = 'x', task = {\n targets = {\n  x_p = {value = 0} } } }",
                  "lv.lua:3: task.targets.x_p.tol: missing"},
        ErrorCase{"return { name = 'x', task = {\n targets = {\n  p = {value = {0, 0}, tol = 1},\n  x_p = {value = 0, tol = 1} } } }",
                  "lv.lua:3: task.targets.p: sets x_p a second time"},
        ErrorCase{"return { name = 'x', task = {\n targets = {x_p = {value = 0, tol = 1}},\n stages = {} } }",
                  "lv.lua:3: task.stages: give either targets"},
        ErrorCase{"return { name = 'x', task = {\n forbidden = {\n  {shape = 'triangle'} } } }",
                  "lv.lua:3: task.forbidden[1].shape: unknown shape 'triangle'"},
        ErrorCase{"return { name = 'x', task = {\n forbidden = {\n  {shape = 'box', min = {0, 0}, max = {-1, 1}} } } }",
                  "lv.lua:3: task.forbidden[1].max: must be above and right of min"},
        ErrorCase{"return { name = 'x',\n medals = {bronze = 1, silver = 2, gold = 3} }", "lv.lua:2: medals: needs a score function"},
        ErrorCase{"return { name = 'x', score = function() end,\n medals = {bronze = 3, silver = 2, gold = 1} }",
                  "lv.lua:2: medals.silver: thresholds must satisfy"},
        ErrorCase{"return { name = 'x',\n score = 5 }", "lv.lua:2: score: expected a function, got number"},
        ErrorCase{"return { name = 'x', callbacks = {\n rate = 1000 } }", "lv.lua:2: callbacks.rate: must be from 10 to 100"},
        ErrorCase{"return { name = 'x', scene = {\n plots = {'u_a',\n 'enrgy'} } }",
                  "lv.lua:3: scene.plots[2]: unknown channel 'enrgy' (did you mean 'energy'?)"},
        ErrorCase{"return { name = 'x',\n demo_bot = '../../etc/passwd' }", "lv.lua:2: demo_bot: bad module name"},
        ErrorCase{"return { name = 'x', scene = { props = {\n { mesh = '../secret.obj', position = {0, 0, 0} } } } }",
                  "lv.lua:2: scene.props[1].mesh: '../secret.obj' must be a relative path under assets/ without '..'"},
        ErrorCase{"return { name = 'x', scene = { props = {\n { mesh = 'meshes/a.png', position = {0, 0, 0} } } } }",
                  "lv.lua:2: scene.props[1].mesh: 'meshes/a.png' is not a .obj, .gltf or .glb file"},
        ErrorCase{"return { name = 'x', scene = { props = {\n { mesh = 'meshes/flag.obj' } } } }",
                  "lv.lua:2: scene.props[1].position: required"},
        ErrorCase{"return { name = 'x', scene = { props = {\n { mesh = 'meshes/flag.obj', position = {0, 0, 0},\n colour = {2, 0, 0} } } } }",
                  "lv.lua:3: scene.props[1].colour: each of {r, g, b} must be in [0, 1]"},
        ErrorCase{"return { name = 'x', scene = { props = {\n { mesh = 'meshes/flag.obj', position = {0, 0, 0}, sise = 1 } } } }",
                  "lv.lua:2: scene.props[1].sise: unknown key 'sise' (did you mean 'size'?)"},
        ErrorCase{"return { name = 'x', scene = { example_path = {\n {0, 0}, {0.01} } } }",
                  "lv.lua:2: scene.example_path[2]: expected a point {x, y}: two finite numbers in metres"},
        ErrorCase{"return { name = 'x', scene = { example_path = {\n {0, 0}, {0, 0/0} } } }",
                  "lv.lua:2: scene.example_path[2]: expected a point {x, y}: two finite numbers in metres"},
        ErrorCase{"return { name = 'x', scene = { example_path = {\n x = {0, 0} } } }",
                  "lv.lua:1: scene.example_path: expected a list of points {x, y} in metres"},
        ErrorCase{"return 42", "lv.lua:1: the level must return a table, got number"},
        ErrorCase{"return {\n name = 'x',\n", "lv.lua:3: unexpected symbol near <eof>"},
        ErrorCase{"local t = nil\nreturn { name = t.x }", "lv.lua:2: attempt to index a nil value"},
        ErrorCase{"while true do end", "lv.lua:1: instruction quota"},
        ErrorCase{"local level = {\n name = 'x',\n extra = true }\nreturn level", "lv.lua:3: extra: unknown key 'extra'"}));

TEST(LevelLoader, MemoryCapStopsAGreedyLevel) {
  // A small cap keeps the test fast; the mechanism is the sandbox's.
  LevelLoadOptions options;
  options.limits.memoryLimitBytes = std::size_t{4} << 20;
  try {
    LevelLoader(options).loadSource("local t = {}\nfor i = 1, 1e8 do t[i] = string.rep('x', 64) .. i end", "lv.lua");
    FAIL() << "expected a ScriptError";
  } catch (const ScriptError& e) {
    // Lua reports memory errors without a position: the file's first line.
    EXPECT_THAT(e.what(), StartsWith("lv.lua:1: memory limit of 4 MiB exceeded"));
  }
}

TEST(LevelLoader, AComputedFieldPointsAtTheReturnedTable) {
  // The field is not written in the constructor: its table's line is the best.
  const std::string message = errorOf("local t = {}\nt.name = 5\nreturn t");
  EXPECT_THAT(message, StartsWith("lv.lua:")) << message;
  EXPECT_THAT(message, HasSubstr("name: expected a string, got number"));
}

TEST(LevelLoader, LoadFileNamesThePathAndReadsModules) {
  const test::TempDirectory dir;
  std::filesystem::create_directories(dir.path() / "levels");
  std::filesystem::create_directories(dir.path() / "scripts" / "lib");
  dir.write("scripts/lib/goal.lua", "return { x = -0.04 }");
  const std::string path = dir.write("levels/l.lua",
                                     "local goal = require('lib.goal')\n"
                                     "return { name = 'm', task = { targets = { u_a = {value = goal.x, tol = 0.01} } } }");
  const LoadedLevel level = LevelLoader().loadFile(path);
  EXPECT_EQ(level.def.source, path);
  EXPECT_EQ(level.def.task.stages[0].targets[0].value, -0.04);

  dir.write("levels/bad.lua", "return {\n name = 1 }");
  try {
    LevelLoader().loadFile((dir.path() / "levels" / "bad.lua").string());
    FAIL() << "expected a ScriptError";
  } catch (const ScriptError& e) {
    EXPECT_THAT(e.what(), StartsWith((dir.path() / "levels" / "bad.lua").string() + ":2: name: expected a string"));
  }
}

TEST(LevelLoader, MissingFileOrDirectoryIsAClearError) {
  try {
    LevelLoader().loadFile("/nonexistent/level.lua");
    FAIL() << "expected a ScriptError";
  } catch (const ScriptError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/level.lua:1: no such file");
  }
  const test::TempDirectory dir;
  try {
    LevelLoader().loadFile(dir.path().string());
    FAIL() << "expected a ScriptError";
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()), dir.path().string() + ":1: not a regular file (a directory)");
  }
}

}  // namespace
}  // namespace hemiroll::script
