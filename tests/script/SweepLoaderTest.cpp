// engine/script/SweepLoader: sweep specs into SweepDef (defaults, values,
// ranges, the analysis thresholds), the shipped specs, and one "file:line:
// path: what" message per class of mistake.

#include "engine/script/SweepLoader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "engine/script/ScriptError.h"
#include "tests/support/ErrorMessage.h"

namespace hemiroll::script {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string kSource = HEMIROLL_SOURCE_DIR;

SweepDef load(const std::string& source) { return SweepLoader().loadSource(source, "s.lua"); }

std::string errorOf(const std::string& source) { return test::messageOf<ScriptError>([&] { load(source); }); }

TEST(SweepLoader, MinimalSpecHasThePapersDefaults) {
  const SweepDef d = load("return { axes = { { param = 'k', values = { 8 } } } }");
  EXPECT_EQ(d.source, "s.lua");
  EXPECT_EQ(d.params.radius, 0.04);
  EXPECT_EQ(d.params.shellMass, 0.1);
  EXPECT_EQ(d.params.pointMass, 1.0);
  EXPECT_EQ(d.params.gravity, 9.81);
  EXPECT_EQ(d.rose.r1, 0.015);
  EXPECT_EQ(d.rose.r2, 0.008);
  EXPECT_EQ(d.rose.k, 8.0);
  EXPECT_EQ(d.rose.omega, -std::numbers::pi / 10);
  EXPECT_EQ(d.start, SweepStart::Equilibrium);
  EXPECT_EQ(d.duration, 35.0);
  EXPECT_EQ(d.timeStep, 0.001);
  EXPECT_EQ(d.integrator, "rk4");
  EXPECT_EQ(d.pointCount(), 1);
}

TEST(SweepLoader, ReadsEveryField) {
  const SweepDef d = load(R"(
    return {
      description = "d", params = { R = 0.05, m_s = 0.2, m_p = 0.5, g = 9.8 },
      drive = { kind = "rose", r1 = 0.01, r2 = 0.005, k = 6, Omega = -0.5 },
      start = "rest", duration = 12, dt = 0.002, integrator = "dopri5", tol = 1e-9,
      analysis = { min_rate = 0.01, relative_band = 0.2, absolute_band = 0.005, min_steady_fraction = 0.5,
                   max_relative_spread = 0.1 },
      axes = {
        { param = "Omega", values = { -0.2, -0.1, -0.3 } },
        { param = "m_p", range = { from = 0.1, to = 10, count = 3, log = true } },
        { param = "r2", range = { from = 0.002, to = 0.004, count = 3 } },
      },
    })");
  EXPECT_EQ(d.description, "d");
  EXPECT_EQ(d.params.radius, 0.05);
  EXPECT_EQ(d.params.pointMass, 0.5);
  EXPECT_EQ(d.rose.k, 6.0);
  EXPECT_EQ(d.rose.omega, -0.5);
  EXPECT_EQ(d.start, SweepStart::Rest);
  EXPECT_EQ(d.duration, 12.0);
  EXPECT_EQ(d.timeStep, 0.002);
  EXPECT_EQ(d.integrator, "dopri5");
  EXPECT_EQ(d.tolerance, 1e-9);
  EXPECT_EQ(d.analysis.minRate, 0.01);
  EXPECT_EQ(d.analysis.maxRelativeSpread, 0.1);
  ASSERT_EQ(d.axes.size(), 3u);
  EXPECT_EQ(d.axes[0].param, SweepParam::Omega);
  EXPECT_THAT(d.axes[0].values, ElementsAre(-0.2, -0.1, -0.3));  // the file's order
  EXPECT_EQ(d.axes[1].param, SweepParam::m_p);
  EXPECT_TRUE(d.axes[1].log);
  ASSERT_EQ(d.axes[1].values.size(), 3u);
  EXPECT_EQ(d.axes[1].values[0], 0.1);
  EXPECT_NEAR(d.axes[1].values[1], 1.0, 1e-15);  // geometric: the middle of 0.1 and 10
  EXPECT_EQ(d.axes[1].values[2], 10.0);          // the end exactly as written
  EXPECT_FALSE(d.axes[2].log);
  EXPECT_NEAR(d.axes[2].values[1], 0.003, 1e-18);
  EXPECT_EQ(d.axes[2].values[2], 0.004);
  EXPECT_EQ(d.pointCount(), 27);
}

TEST(SweepLoader, ListedValuesMayBeShownOnALogScale) {
  const SweepDef d = load("return { axes = { { param = 'm_p', values = { 0.5, 1, 2 }, log = true } } }");
  EXPECT_TRUE(d.axes[0].log);
  EXPECT_EQ(d.axes[0].values[1], 1.0);
  EXPECT_THAT(errorOf("return { axes = {\n { param = 'k', values = { -1, 2 }, log = true } } }"),
              HasSubstr("s.lua:2: axes[1].log: a log axis needs values of one sign, none 0"));
  EXPECT_THAT(errorOf("return { axes = {\n { param = 'k', range = { from = 1, to = 2, count = 2 }, log = true } } }"),
              HasSubstr("s.lua:2: axes[1].log: a range says log inside"));
}

TEST(SweepLoader, AListedAxisHasTheCapOfARange) {
  // 1,000,001 values once hung in a quadratic repeat check (issue 19).
  EXPECT_THAT(errorOf("local v = {} for i = 1, 1000001 do v[i] = i end\nreturn { axes = { { param = 'k', values = v } } }"),
              HasSubstr("axes[1].values: 1000001 values; an axis may have at most 100000"));
  EXPECT_THAT(errorOf("return { axes = {\n { param = 'k', values = { 1, 2, 1 } } } }"),
              HasSubstr("axes[1].values[3]: repeats an earlier value; each value once"));
}

TEST(SweepLoader, ANegativeLogRangeIsGeometricInItsMagnitude) {
  const SweepDef d = load("return { axes = { { param = 'Omega', range = { from = -1, to = -0.01, count = 3, log = true } } } }");
  EXPECT_EQ(d.axes[0].values[0], -1.0);
  EXPECT_NEAR(d.axes[0].values[1], -0.1, 1e-15);
  EXPECT_EQ(d.axes[0].values[2], -0.01);
}

// Every mistake: the file and the line of the field, its path, and what.
TEST(SweepLoader, EachMistakeNamesFileLineAndPath) {
  struct Case {
    std::string source, expected;
  };
  const std::vector<Case> cases = {
      {"return {\n  axes = = 1 }", "s.lua:2:"},
      {"return {\n  axis = {} }", "s.lua:2: axis: unknown key 'axis' (did you mean 'axes'?)"},
      {"return {\n  duraton = 3,\n  axes = { { param = 'k', values = { 8 } } } }", "s.lua:2: duraton: unknown key 'duraton' (did you mean 'duration'?)"},
      {"return {\n  params = { m_z = 1 },\n axes = {} }", "s.lua:2: params.m_z: unknown key 'm_z' (did you mean 'm_s'?)"},
      {"return {\n  params = { m_s = 0 } }", "s.lua:2: params.m_s: m_s must be a positive mass in kilograms"},
      {"return {\n  drive = { kind = 'free' } }", "s.lua:2: drive.kind: a sweep runs the rose drive only"},
      {"return {\n  drive = { r1 = '0.01' } }", "s.lua:2: drive.r1: expected a number, got string"},
      {"return {\n  start = 'equilibirum' }", "s.lua:2: start: unknown start 'equilibirum' (did you mean 'equilibrium'?)"},
      {"return {\n  integrator = 'rk5' }", "s.lua:2: integrator: unknown integrator 'rk5'"},
      {"return {\n  dt = -1 }", "s.lua:2: dt: must be a positive number (seconds)"},
      {"return {\n  dt = 1e-9 }", "s.lua:2: dt: duration / dt is more than 10 million steps"},
      {"return {\n  analysis = { min_steady_fraction = 2 } }", "s.lua:2: analysis.min_steady_fraction: must be at most 1"},
      {"return { description = 'x' }", "s.lua:1: axes: missing"},
      {"return {\n  axes = {} }", "s.lua:2: axes: empty; give at least one axis"},
      {"return {\n  axes = {\n    { param = 'omega', values = { 1 } } } }",
       "s.lua:3: axes[1].param: unknown parameter 'omega' (did you mean 'Omega'?)"},
      {"return { axes = {\n  { param = 'k', values = { 1 } },\n  { param = 'k', values = { 2 } } } }",
       "s.lua:3: axes[2].param: 'k' is already axis 1; each parameter once"},
      {"return { axes = {\n  { param = 'k' } } }", "s.lua:2: axes[1]: give either values = { ... } or range"},
      {"return { axes = {\n  { param = 'k', values = { 1 }, range = { from = 1, to = 2, count = 2 } } } }",
       "s.lua:2: axes[1].range: give either values"},
      {"return { axes = {\n  { param = 'k', values = {} } } }", "s.lua:2: axes[1].values: empty; give at least one value"},
      {"return { axes = {\n  { param = 'k', values = { 1,\n 2, 1 } } } }", "s.lua:3: axes[1].values[3]: repeats an earlier value"},
      {"return { axes = {\n  { param = 'r1', values = { 0.01,\n -0.01 } } } }",
       "s.lua:3: axes[1].values[2]: r1 must be a length >= 0 in metres"},
      {"return { axes = {\n  { param = 'k', values = { 1, 'x' } } } }", "s.lua:2: axes[1].values[2]: expected a number, got string"},
      {"return { axes = {\n  { param = 'k', range = { from = 1, to = 2,\n count = 1 } } } }",
       "s.lua:3: axes[1].range.count: expected a whole number from 2 to 100000"},
      {"return { axes = {\n  { param = 'k', range = { from = 1, to = 1, count = 2 } } } }", "s.lua:2: axes[1].range.to: equals from"},
      {"return { axes = {\n  { param = 'k', range = { from = -1, to = 1, count = 2,\n log = true } } } }",
       "s.lua:3: axes[1].range.log: a log range needs from and to of the same sign, neither 0"},
      {"return { axes = {\n  { param = 'm_s', range = { from = 0,\n to = 1, count = 2 } } } }",
       "s.lua:2: axes[1].range.from: m_s must be a positive mass in kilograms"},
      {"return { axes = {\n  { param = 'k', range = { from = 1, to = 2, count = 1000 } },\n  { param = 'Omega', range = { from = 1, to = 2, count = 1001 } } } }",
       "s.lua:3: axes[2]: the grid would have more than 1000000 points"},
      {"return { axes = {\n  'k' } }", "s.lua:2: axes[1]: expected an axis table"},
      {"while true do end", "instruction quota"},
      {"return 5", "s.lua:1: the sweep spec must return a table, got number"},
  };
  for (const Case& c : cases) {
    const std::string error = errorOf(c.source);
    EXPECT_THAT(error, HasSubstr(c.expected)) << c.source;
    EXPECT_THAT(error, StartsWith("s.lua:")) << c.source;
  }
}

TEST(SweepLoader, MissingFileIsOneSentenceWithLineOne) {
  try {
    SweepLoader().loadFile("/nonexistent/sweep.lua");
    FAIL() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_THAT(e.what(), StartsWith("/nonexistent/sweep.lua:1: no such file"));
  }
}

TEST(SweepLoader, TheShippedSpecsLoad) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kSource + "/levels/sweeps")) {
    if (entry.path().extension() != ".lua") continue;
    const SweepDef d = SweepLoader().loadFile(entry.path().string());
    EXPECT_GE(d.axes.size(), 2u) << entry.path();
    EXPECT_GT(d.pointCount(), 1) << entry.path();
    ++count;
  }
  EXPECT_GE(count, 3);
}

// docs/SWEEP.md's example spec (its first ```lua block) loads as written.
TEST(SweepLoader, TheDocsExampleLoads) {
  std::ifstream in(kSource + "/docs/SWEEP.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::size_t begin = doc.find("```lua\n");
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = doc.find("```", begin + 7);
  ASSERT_NE(end, std::string::npos);
  const SweepDef d = SweepLoader().loadSource(doc.substr(begin + 7, end - begin - 7), "SWEEP.md");
  EXPECT_EQ(d.axes.size(), 2u);
  EXPECT_EQ(d.start, SweepStart::Equilibrium);
}

}  // namespace
}  // namespace hemiroll::script
