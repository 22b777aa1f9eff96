#pragma once
// engine/script: the Lua 5.4 runtime of hemiroll.
//
// Owns: the sandboxed Lua state (LuaSandbox: allow-list environment, text-only
// chunks, an instruction quota through a count hook, a memory cap through the
// allocator), the conversion of every Lua error into a ScriptError that names
// "file:line" or "file: field.path", typed reads of script data
// (LuaTableReader), the one loader of Lua data files (DataFileLoader: read,
// sandbox, run, hand the returned table to the kind's reader, every error
// "file:line:" with the line of the field from LevelSourceMap) under levels,
// protocols, sweep specs and scenarios, and loading scenario files into
// plain C++ definitions (ScenarioLoader -> ScenarioDef), including proxy
// trajectories written in Lua (LuaProxyTrajectory). Levels
// (docs/LEVELS.md): loading level files (LevelLoader -> LevelDef +
// LevelScript, every error "file:line:"), level callbacks and scoring
// (LevelScript), and the engine services `require` (scripts/ modules only)
// and the seeded `hemiroll.random` (ScriptModules). Bots
// (docs/RUN.md): loading a bot module in its own sandbox and calling its
// init/act with a read-only observation view that allocates nothing per tick
// (BotScript, BotObservation); the trial loop that feeds it is the game's.
// Research protocols (docs/PROTOCOLS.md): loading a protocol file
// (ProtocolLoader -> ProtocolDef, errors "file:line:" as for levels, level
// files checked to exist); running a session is the game's. Parameter sweeps
// (docs/SWEEP.md): loading a sweep spec (SweepLoader -> SweepDef, errors
// "file:line:" as for levels); running one is the game's.
//
// What a script can reach: the base functions assert, error, getmetatable,
// ipairs, next, pairs, pcall, print (to stderr), rawequal, rawlen, select,
// setmetatable (without __gc), tonumber, tostring, type, xpcall, _VERSION, _G;
// copies of string (no dump), table, math (no random, randomseed) and utf8.
// Nothing else: no io, os, debug, package, coroutine, load, loadfile, dofile,
// collectgarbage, rawget, rawset; `require` only where the engine installs
// its own (ScriptModules.h); the string metatable is hidden.
//
// Must not know: any particular level or protocol (the judge evaluates what a
// level declares), the game, commands, command-line flags, files other than
// the script it is asked to load, modules under the scripts/ directory it is
// given and (only whether they exist) the level files a protocol names,
// threads, clocks, devices, rendering. Depends on engine/task (the model
// it fills: LevelDef, TaskJudge, ProtocolDef and ProtocolPlan, SweepDef,
// ScenarioDef, DeviceProfileDef; Task.h), engine/physics and Lua.
//
// Known limit: the quota counts Lua VM instructions, so a single long call
// into a C library function (a pathological string.find pattern) is not
// interrupted; the memory cap still bounds what it can allocate.

#include "engine/task/Task.h"
#include "engine/script/TaskNames.h"
#include "engine/script/BotObservation.h"
#include "engine/script/BotScript.h"
#include "engine/script/DataFileLoader.h"
#include "engine/script/LevelLoader.h"
#include "engine/script/LevelScript.h"
#include "engine/script/LuaProxyTrajectory.h"
#include "engine/script/LuaSandbox.h"
#include "engine/script/ProtocolLoader.h"
#include "engine/script/LuaTableReader.h"
#include "engine/script/SandboxLimits.h"
#include "engine/script/ScenarioLoader.h"
#include "engine/script/ScriptError.h"
#include "engine/script/ScriptModules.h"
#include "engine/script/ScriptSourceFile.h"
