// engine/script/BotScript: a bot module's contract (name, init, act), the
// read-only observation, failures as positioned ScriptErrors, and a per-tick
// call that creates no Lua objects.

#include "engine/script/BotScript.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "engine/script/ScriptError.h"
#include "tests/support/ErrorMessage.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::script {
namespace {

using ::testing::HasSubstr;
using test::TempDirectory;

struct BotFile {
  TempDirectory dir;
  std::string path;
  explicit BotFile(const std::string& source, const std::string& name = "bot.lua") : path(dir.write(name, source)) {}
};

std::string loadError(const std::string& source) {
  const BotFile file(source);
  return test::messageOf<ScriptError>([&] { BotScript bot(file.path); });
}

std::string actError(const std::string& source, const BotObservation& obs = {}) {
  const BotFile file(source);
  BotScript bot(file.path);
  return test::messageOf<ScriptError>([&] { bot.act(obs); });
}

TEST(BotScript, ActSeesTheObservationAndReturnsThePose) {
  const BotFile file(
      "return {name = 'probe', act = function(t, obs)\n"
      "  return obs.mass.x + obs.state.u_a, obs.face_y.y * t, obs.time + obs.proxy_distance\n"
      "end}");
  BotScript bot(file.path);
  EXPECT_EQ(bot.name(), "probe");
  BotObservation obs;
  obs.time = 2.0;
  obs.mass = {0.25, 0.0, 0.0};
  obs.state[7] = 0.5;  // u_a
  obs.faceY = {0.0, 3.0, 0.0};
  obs.proxyDistance = 0.125;
  const BotAction a = bot.act(obs);
  // Values chosen exact in binary, so the sums are exact.
  EXPECT_EQ(a.position, (Triple3{0.75, 6.0, 2.125}));
  EXPECT_FALSE(a.hasVelocity);
}

// The last two vectors of the observation: the coupling's force and what the
// hand feels (the device's rendered force), each its own table.
TEST(BotScript, ForceAndDeviceForceAreSeparateVectors) {
  const BotFile file(
      "return {name = 'feel', act = function(t, obs)\n"
      "  return obs.force.x, obs.device_force.y, obs.device_force.z + obs.proxy.x\n"
      "end}");
  BotScript bot(file.path);
  BotObservation obs;
  obs.force = {1.5, 0.0, 0.0};
  obs.deviceForce = {0.0, -0.25, 4.0};
  obs.proxy = {0.5, 0.0, 0.0};
  EXPECT_EQ(bot.act(obs).position, (Triple3{1.5, -0.25, 4.5}));
}

// The engagement ramp, as the HUD shows it ("holding, force 50%").
TEST(BotScript, TheForceShareIsAScalarOfTheObservation) {
  const BotFile file("return {name = 'share', act = function(t, obs) return obs.force_share, 0, 0 end}");
  BotScript bot(file.path);
  BotObservation obs;
  obs.forceShare = 0.375;
  EXPECT_EQ(bot.act(obs).position, (Triple3{0.375, 0.0, 0.0}));
}

TEST(BotScript, SixValuesGiveAVelocity) {
  const BotFile file("return {name = 'v', act = function(t, obs) return 1, 2, 3, 4, 5, 6 end}");
  BotScript bot(file.path);
  const BotAction a = bot.act({});
  EXPECT_TRUE(a.hasVelocity);
  EXPECT_EQ(a.velocity, (Triple3{4.0, 5.0, 6.0}));
}

TEST(BotScript, TheObservationFollowsEachTick) {
  const BotFile file("return {name = 'echo', act = function(t, obs) return obs.state.psi, obs.stage, t end}");
  BotScript bot(file.path);
  BotObservation obs;
  for (int i = 0; i < 3; ++i) {
    obs.time = 0.001 * i;
    obs.state[11] = 10.0 * i;
    obs.stage = i;
    const BotAction a = bot.act(obs);
    EXPECT_EQ(a.position[0], 10.0 * i);
    EXPECT_EQ(a.position[1], i + 1) << "stage counts from 1 in Lua";
    EXPECT_EQ(a.position[2], 0.001 * i);
  }
}

TEST(BotScript, AViewKeptAcrossTicksReadsTheCurrentTick) {
  const BotFile file(
      "local s, m\n"
      "return {name = 'keep', act = function(t, obs)\n"
      "  if not s then s, m = obs.state, obs.mass end\n"
      "  return s.x_p, m.y, 0\nend}");
  BotScript bot(file.path);
  BotObservation obs;
  for (int i = 1; i <= 3; ++i) {
    obs.state[0] = 0.5 * i;
    obs.mass[1] = 0.25 * i;
    const BotAction a = bot.act(obs);
    EXPECT_EQ(a.position[0], 0.5 * i);
    EXPECT_EQ(a.position[1], 0.25 * i);
  }
}

TEST(BotScript, TargetsAreNilUnlessSet) {
  const BotFile file(
      "return {name = 't', act = function(t, obs)\n"
      "  local u = obs.target.u_a\n"
      "  return u == nil and -1 or u, obs.tolerance.u_a or -1, obs.target.x_p == nil and 1 or 0\n"
      "end}");
  BotScript bot(file.path);
  BotObservation obs;
  EXPECT_EQ(bot.act(obs).position, (Triple3{-1.0, -1.0, 1.0}));
  obs.targetSet[7] = true;
  obs.target[7] = -0.04;
  obs.tolerance[7] = 0.004;
  EXPECT_EQ(bot.act(obs).position, (Triple3{-0.04, 0.004, 1.0}));
  obs.targetSet[7] = false;  // a stage without it
  EXPECT_EQ(bot.act(obs).position, (Triple3{-1.0, -1.0, 1.0}));
}

TEST(BotScript, InitGetsTheLevelAndTheSeed) {
  const BotFile file(
      "local k, s, r\n"
      "return {name = 'i', init = function(level, seed) k, s, r = level.kr, seed, level.workspace.radius end,\n"
      "  act = function(t, obs) return k, s, r end}");
  BotScript bot(file.path);
  BotLevelInfo info;
  info.coupling.stiffness = 125.0;
  info.workspaceRadius = 0.5;
  bot.init(info, 42);
  EXPECT_EQ(bot.act({}).position, (Triple3{125.0, 42.0, 0.5}));
}

TEST(BotScript, ObservationIsReadOnly) {
  EXPECT_THAT(actError("return {name = 'w', act = function(t, obs)\n  obs.time = 5\n  return 0, 0, 0 end}"),
              HasSubstr("bot.lua:2: obs is read-only (tried to set 'time')"));
  EXPECT_THAT(actError("return {name = 'w', act = function(t, obs)\n\n  obs.mass.x = 5\n  return 0, 0, 0 end}"),
              HasSubstr("bot.lua:3: obs is read-only (tried to set 'x')"));
  EXPECT_THAT(actError("return {name = 'w', act = function(t, obs) setmetatable(obs, nil) return 0, 0, 0 end}"),
              HasSubstr("cannot change a protected metatable"));
}

TEST(BotScript, BadBotsAreRefusedAtLoadNamingTheFile) {
  EXPECT_THAT(loadError("return 5"), HasSubstr("bot.lua: a bot must return a table"));
  EXPECT_THAT(loadError("return {act = function() end}"), HasSubstr("bot.lua: name: missing"));
  EXPECT_THAT(loadError("return {name = 'x'}"), HasSubstr("bot.lua: act: missing"));
  EXPECT_THAT(loadError("return {name = 'x', act = 3}"), HasSubstr("bot.lua: act: expected a function"));
  EXPECT_THAT(loadError("return {name = 'x', act = function() end, init = 'no'}"),
              HasSubstr("bot.lua: init: expected a function"));
  EXPECT_THAT(loadError("local x = \nreturn {}"), HasSubstr("bot.lua:2:"));
  EXPECT_THAT(loadError("local f = io.open('/etc/passwd')\nreturn {}"), HasSubstr("bot.lua:1:"));
  EXPECT_THAT(loadError("os.exit(1)"), HasSubstr("bot.lua:1:"));
}

TEST(BotScript, BadReturnsNameTheFunctionAndTheTime) {
  BotObservation obs;
  obs.time = 0.5;
  EXPECT_THAT(actError("return {name = 'n',\n  act = function(t, obs) return 0 / 0, 0, 0 end}", obs),
              HasSubstr("bot.lua:2: act(t = 0.5) returned nan as value 1 (x); expected a finite number"));
  EXPECT_THAT(actError("return {name = 'n', act = function(t, obs) return 0, 0 end}"),
              HasSubstr("bot.lua:1: act(t = 0) returned 2 values"));
  EXPECT_THAT(actError("return {name = 'n', act = function(t, obs) return 0, 'y', 0 end}"),
              HasSubstr("returned string as value 2 (y)"));
  EXPECT_THAT(actError("return {name = 'n', act = function(t, obs) return 0, 0, 1/0, 0, 0, 0 end}"),
              HasSubstr("returned inf as value 3 (z)"));
}

TEST(BotScript, ErrorsAndQuotaInActArePositioned) {
  EXPECT_THAT(actError("return {name = 'e', act = function(t, obs)\n  error('lost')\nend}"),
              HasSubstr("bot.lua:2: lost (in act, t = 0)"));
  EXPECT_THAT(actError("return {name = 'q', act = function(t, obs)\n  while true do end\nend}"),
              HasSubstr("bot.lua:2: instruction quota"));
}

TEST(BotScript, InitFailureIsPositioned) {
  const BotFile file("return {name = 'i', init = function()\n  error('no init')\nend, act = function() end}");
  BotScript bot(file.path);
  try {
    bot.init({}, 0);
    ADD_FAILURE() << "init should have failed";
  } catch (const ScriptError& e) {
    EXPECT_THAT(e.what(), HasSubstr("bot.lua:2: no init"));
  }
}

TEST(BotScript, ATickCreatesNoLuaObjects) {
  // The bot itself only does arithmetic; anything the memory count gains
  // would be the host's tables or strings per tick.
  const BotFile file(
      "return {name = 'flat', act = function(t, obs)\n"
      "  local m = obs.mass\n"
      "  return m.x + obs.state.x_p, m.y + obs.face_x.x, m.z + (obs.target.u_a or 0)\n"
      "end}");
  BotScript bot(file.path);
  BotObservation obs;
  obs.targetSet[7] = true;
  bot.act(obs);  // first tick writes the task fields
  const std::size_t before = bot.sandbox().memoryInUse();
  for (int i = 0; i < 10000; ++i) {
    obs.time = 0.001 * i;
    obs.mass[0] = 1e-3 * i;
    obs.state[0] = std::sin(0.01 * i);
    bot.act(obs);
  }
  EXPECT_EQ(bot.sandbox().memoryInUse(), before);
}

TEST(BotScript, RequireAndRandomComeFromTheEngine) {
  const TempDirectory dir;
  dir.write("lib_mod.lua", "return {twice = function(x) return 2 * x end}");
  const std::string path = dir.write(
      "bot.lua",
      "local m = require('lib_mod')\n"
      "return {name = 'r', act = function(t, obs) return m.twice(3), hemiroll.random(), hemiroll.seed() end}");
  BotLoadOptions options;
  options.scriptsDir = dir.path().string();
  options.seed = 7;
  BotScript a(path, options), b(path, options);
  const BotAction first = a.act({});
  EXPECT_EQ(first.position[0], 6.0);
  EXPECT_EQ(first.position[2], 7.0);
  EXPECT_EQ(first.position, b.act({}).position) << "same seed, same sequence";
  options.seed = 8;
  BotScript c(path, options);
  EXPECT_NE(c.act({}).position[1], first.position[1]);
}

TEST(BotScript, ABotInBotsRequiresFromTheScriptsDirectoryAboveIt) {
  const TempDirectory dir;
  std::filesystem::create_directories(dir.path() / "scripts" / "bots");
  std::filesystem::create_directories(dir.path() / "scripts" / "lib");
  dir.write("scripts/lib/twice.lua", "return function(x) return 2 * x end");
  const std::string path =
      dir.write("scripts/bots/b.lua", "local twice = require('lib.twice')\n"
                                      "return {name = 'b', act = function(t, obs) return twice(1), twice(2), twice(3) end}");
  BotScript bot(path);
  EXPECT_EQ(bot.act({}).position, (Triple3{2.0, 4.0, 6.0}));
}

// In a research session a Lua bot's init sees the trial's place
// (level.trial) and the participant's memory (level.memory), a table whose
// name = number entries go back into the memory after the trial.
TEST(BotScript, InASessionInitSeesThePlaceAndKeepsAMemoryAcrossTrials) {
  const BotFile file(
      "local seen\n"
      "return {name = 'learner',\n"
      "  init = function(level, seed)\n"
      "    level.memory.trials = (level.memory.trials or 0) + 1\n"
      "    level.memory.last_block = level.trial.block\n"
      "    seen = level.trial.block_name .. ' ' .. level.trial.group .. ' ' .. level.trial.guidance\n"
      "  end,\n"
      "  act = function(t, obs) return #seen, 0, 0 end}");
  BotMemory memory;
  BotLevelInfo info;
  info.place.inSession = true;
  info.place.block = 3;
  info.place.blockName = "training";
  info.place.group = "guided";
  info.place.guidance = "autopilot";
  info.memory = &memory;
  for (int trial = 1; trial <= 2; ++trial) {
    BotScript bot(file.path);
    bot.init(info, 1);
    EXPECT_EQ(bot.act({}).position[0], std::string("training guided autopilot").size());
    bot.endTrial();
    EXPECT_EQ(memory.get("trials"), trial);
    EXPECT_EQ(memory.get("last_block"), 3.0);
  }
  // Outside a session: no trial, no memory.
  const BotFile outside("return {name = 'o', init = function(level) assert(level.trial == nil and level.memory == nil) end,\n"
                        "  act = function() return 0, 0, 0 end}");
  BotScript plain(outside.path);
  EXPECT_NO_THROW(plain.init(BotLevelInfo{}, 1));
  EXPECT_NO_THROW(plain.endTrial());
}

TEST(BotScript, AMemoryThatBreaksTheRulesIsRefusedAndTheOldOneKept) {
  const BotFile file("return {name = 'm', init = function(level) level.memory.note = 'text' end,\n"
                     "  act = function() return 0, 0, 0 end}");
  BotMemory memory;
  memory.set("kept", 1.0);
  BotLevelInfo info;
  info.memory = &memory;
  BotScript bot(file.path);
  bot.init(info, 1);
  EXPECT_THAT(test::messageOf<ScriptError>([&] { bot.endTrial(); }),
              HasSubstr("bot memory: level.memory holds "));
  EXPECT_EQ(memory.get("kept"), 1.0);
  EXPECT_FALSE(memory.get("note"));
}

}  // namespace
}  // namespace hemiroll::script
