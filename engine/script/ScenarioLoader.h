#pragma once
// Reads a scenario file (docs/SCENARIOS.md) into a ScenarioDef: the
// scenario's reader on top of DataFileLoader. The file is Lua run in a fresh
// LuaSandbox; it must return a plain table
//   { params = {...}, initial = {...}, drive = {...}, duration, dt, integrator }.
// Anything wrong with it — syntax, run-time error, quota, a missing or
// mistyped field, an unknown name, a value out of range — throws ONE
// ScriptError "file:line: path: what", as LevelLoader does. A proxy
// function is called once at t = 0 while loading, so that one that returns
// the wrong things fails here.

#include <string>
#include <string_view>

#include "engine/script/SandboxLimits.h"
#include "engine/task/ScenarioDef.h"
#include "engine/script/TaskNames.h"

namespace hemiroll::script {

class ScenarioLoader {
 public:
  explicit ScenarioLoader(const SandboxLimits& limits = {}) : limits_(limits) {}

  ScenarioDef loadFile(const std::string& path) const;
  // The same from text in memory; `name` stands for the file in messages.
  ScenarioDef loadSource(std::string_view source, const std::string& name) const;

 private:
  SandboxLimits limits_;
};

}  // namespace hemiroll::script
