#pragma once
// Reads a sweep spec (docs/SWEEP.md) into a SweepDef: the spec's reader on
// top of DataFileLoader. The file is Lua run in a fresh LuaSandbox (no
// require, no random: a spec is data) and must return a plain table
//   { params = {...}, drive = {...}, start = "equilibrium", duration, dt,
//     integrator, tol, axes = { {param = "k", values = {...}},
//                               {param = "Omega", range = {from, to, count, log}} } }.
// Anything wrong with it - syntax, run-time error, quota, an unknown key or
// parameter (with the nearest allowed name), a wrong type, a value out of
// range for its parameter, a repeated axis or value, a grid too large -
// throws ONE ScriptError "file:line: path: what", as ProtocolLoader does.

#include <string>
#include <string_view>

#include "engine/script/SandboxLimits.h"
#include "engine/task/SweepDef.h"
#include "engine/script/TaskNames.h"

namespace hemiroll::script {

class SweepLoader {
 public:
  explicit SweepLoader(const SandboxLimits& limits = {}) : limits_(limits) {}

  SweepDef loadFile(const std::string& path) const;
  // The same from text; `name` stands for the file in messages.
  SweepDef loadSource(std::string_view source, const std::string& name) const;

 private:
  SandboxLimits limits_;
};

}  // namespace hemiroll::script
