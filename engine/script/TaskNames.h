#pragma once
// The task model's names (engine/task, namespace hemiroll::task) seen
// unqualified in the Lua layer that fills it: the loaders write LevelDef,
// not task::LevelDef. Included by every engine/script file that includes a
// task header.

namespace hemiroll::task {}

namespace hemiroll::script {
using namespace hemiroll::task;
}  // namespace hemiroll::script
