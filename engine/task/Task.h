#pragma once
// engine/task: the task model of hemiroll, as plain C++ data and code that
// knows no Lua.
//
// Owns: what a level is (LevelDef: the model's parameters, coupling,
// initial state, scoring, per-device mappings) and its task (TaskDef:
// judged variables, stages, targets, zones, holds); judging that task every
// tick (TaskJudge, allocation-free) and the trial's summary
// (TrialSummary, TrialSummaryAccumulator); research protocols as data
// (ProtocolDef: blocks, conditions, groups, overrides) and their
// deterministic trial plan (ProtocolPlan, seeded by EngineRandom, which
// also backs the levels' `hemiroll.random`); sweep specs (SweepDef),
// scenarios and their drives (ScenarioDef, DriveDef,
// ConstantProxyTrajectory) and device profiles (DeviceProfileDef).
//
// Must not know: Lua (engine/script, above it, reads the files and fills
// these definitions; a Lua-backed proxy trajectory reaches a DriveDef only
// through the physics' ProxyTrajectory interface), files, threads, clocks,
// devices, the game. Depends on engine/physics and the standard library.
// The build checks it (hemiroll_task links and includes no Lua and no
// engine/script: cmake/HemirollLayers.cmake).
//
// Its names are in namespace hemiroll::task; the loaders of engine/script
// see them unqualified (engine/script/TaskNames.h).

#include "engine/task/ConstantProxyTrajectory.h"
#include "engine/task/DeviceProfileDef.h"
#include "engine/task/DriveDef.h"
#include "engine/task/EngineRandom.h"
#include "engine/task/LevelDef.h"
#include "engine/task/ProtocolDef.h"
#include "engine/task/ProtocolPlan.h"
#include "engine/task/ScenarioDef.h"
#include "engine/task/SweepDef.h"
#include "engine/task/TaskDef.h"
#include "engine/task/TaskJudge.h"
#include "engine/task/TrialSummary.h"
#include "engine/task/TrialSummaryAccumulator.h"
