#pragma once
// Reads a level's `task` table (docs/LEVELS.md, "task") into a TaskDef:
// targets (single variables or the paper's vector groups, each with a
// per-component tolerance), hold, time limit, stages, failure conditions,
// forbidden zones. Failures throw through LuaTableReader::fail.

#include "engine/script/LuaTableReader.h"
#include "engine/task/TaskDef.h"
#include "engine/script/TaskNames.h"

namespace hemiroll::script {

// `top` is the level table; an absent `task` leaves the defaults (watch-only).
void readLevelTask(const LuaTableReader& top, TaskDef& task);

}  // namespace hemiroll::script
