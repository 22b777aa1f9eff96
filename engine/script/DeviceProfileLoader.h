#pragma once
// Reads a device profile file (devices/*.lua, docs/UDP_BRIDGE.md "Device
// profiles") into a DeviceProfileDef, on top of DataFileLoader: Lua run in a
// fresh sandbox that must return a plain table of numbers and strings with
// SI units in the keys' names. Anything wrong - syntax, an unknown key (with
// the nearest allowed name), a missing or non-positive figure, a continuous
// force above the peak - throws ONE ScriptError "file:line: key: what".

#include <string>
#include <string_view>

#include "engine/task/DeviceProfileDef.h"
#include "engine/script/TaskNames.h"
#include "engine/script/SandboxLimits.h"

namespace hemiroll::script {

class DeviceProfileLoader {
 public:
  explicit DeviceProfileLoader(SandboxLimits limits = {}) : limits_(limits) {}

  DeviceProfileDef loadFile(const std::string& path) const;
  // The same from text; `name` stands for the file in messages and gives the profile's name (its stem).
  DeviceProfileDef loadSource(std::string_view source, const std::string& name) const;

 private:
  SandboxLimits limits_;
};

}  // namespace hemiroll::script
