#pragma once
// A bot: a Lua module that plays a level by moving the proxy. The file
// returns a table
//   { name = "...", init = function(level_info, seed) ... end,  -- optional
//     act = function(t, obs) return x, y, z [, vx, vy, vz] end }
// act gives the proxy in the scene frame [m] (and optionally its velocity
// [m/s]; the device derives one otherwise). obs is one read-only table,
// built once and refreshed before every call (docs/RUN.md lists its fields);
// a bot must not keep references into it across ticks expecting old values.
//
// The bot's sandbox has the engine services of ScriptModules.h: require()
// for scripts/ modules and the seeded hemiroll.random.
//
// Every call runs under the sandbox's per-call instruction quota and memory
// cap, in the bot's own sandbox (a bot cannot see or change the level's
// state). Any failure throws ScriptError naming "file:line".
//
// Cost per tick: one Lua call. obs and its nested tables are empty views
// whose reads go to a C function that reads the C++ BotObservation of the
// call in progress, so nothing is written into Lua per tick and a bot pays
// only for the fields it reads; no Lua object is created per tick
// (tests/script/BotScriptTest checks that the memory in use stays flat).
// The views are not iterable (pairs(obs) yields nothing).

#include <cstdint>
#include <memory>
#include <string>

#include "engine/script/BotObservation.h"
#include "engine/script/BotPolicy.h"
#include "engine/script/LuaSandbox.h"

namespace hemiroll::script {

struct ObservationViews;  // BotScript.cpp

struct BotLoadOptions {
  SandboxLimits limits;
  // Where the bot's require() finds modules; "" = the directory above a
  // bot in a bots/ directory (scripts/bots/x.lua -> scripts/, so
  // require("lib.vec") finds scripts/lib/vec.lua), else defaultScriptsDir.
  std::string scriptsDir;
  std::uint64_t seed = 0;  // hemiroll.random's seed (also passed to init)
};

class BotScript final : public BotPolicy {
 public:
  // Loads and checks the bot file (throws ScriptError: "bot.lua: act: missing").
  explicit BotScript(const std::string& path, const BotLoadOptions& options = {});
  ~BotScript();
  BotScript(const BotScript&) = delete;
  BotScript& operator=(const BotScript&) = delete;

  const std::string& name() const override { return name_; }
  const std::string& path() const { return path_; }
  LuaSandbox& sandbox() { return *sandbox_; }

  // Headless: the bot's Lua gets the trial's time budget (SandboxLimits::
  // trialSeconds and per simulated second, from the start of this trial);
  // real time: every act the tick's CPU budget.
  void setTiming(const TrialTiming& timing) override;
  // Calls init(level_info, seed) when the bot has one.
  void init(const BotLevelInfo& info, std::int64_t seed) override;
  // Calls act(obs.time, obs) with obs reading `obs` (only during this call).
  BotAction act(const BotObservation& obs) override;
  // In a session: level.memory (a table of name = number the bot may change
  // during the trial) back into the participant's memory.
  void endTrial() override;

 private:
  void buildObservation();

  std::shared_ptr<LuaSandbox> sandbox_;
  std::unique_ptr<ObservationViews> views_;
  std::string path_;
  std::string name_;
  std::string actAt_;   // "file:line" of act's definition
  int actRef_ = 0;      // registry references
  int initRef_ = 0;     // LUA_NOREF when the bot has no init
  int obsRef_ = 0;      // the read-only view handed to act
  int memoryRef_ = -2;  // LUA_NOREF (-2) outside a session: level.memory
  BotMemory* memory_ = nullptr;
};

}  // namespace hemiroll::script
