#pragma once
// Device profiles (devices/*.lua, docs/UDP_BRIDGE.md "Device profiles"):
// where one named on the command line, in the settings or by a protocol is
// found, and what it becomes in a trial: the device's spec (the clamp, the
// stiffest coupling, the reach a bot is held to) and the safety layer's
// limits (rate limit, workspace box, continuous rating). A level whose
// coupling the profile cannot render is refused before its trial, in one
// sentence naming both.

#include <filesystem>
#include <string>
#include <vector>

#include "engine/haptics/DeviceSpec.h"
#include "engine/haptics/ForceSafety.h"
#include "engine/physics/ForceCoupling.h"
#include "engine/task/DeviceProfileDef.h"

namespace hemiroll::game {

// The folders searched for NAME.lua, in order: $HEMIROLL_DEVICES, ./devices,
// beside the running program and one level up (build/hemiroll in a checkout).
std::vector<std::filesystem::path> deviceProfileFolders();

// The names of the profiles those folders hold, sorted, each once.
std::vector<std::string> deviceProfileNames();

// A profile by name ("touch") or file ("my/lab_touch.lua": a name with a
// '/' or ending in .lua is a file). Throws script::ScriptError: for an
// unknown name, naming the folders searched and the profiles they hold;
// for a bad file, the loader's "file:line: key: what".
task::DeviceProfileDef loadDeviceProfile(const std::string& nameOrFile);

// The profile a protocol names (its `device_profile`): a relative .lua file
// is looked for beside the protocol first, then as loadDeviceProfile does.
task::DeviceProfileDef loadProtocolDeviceProfile(const std::string& nameOrFile, const std::string& protocolPath);

// The device's limits: maxForce the peak force, maxStiffness the profile's,
// workspaceRadius the box's smallest half-extent (a sphere inside it: what a
// bot's reach is held to), force output yes; named by the profile's model.
haptics::DeviceSpec deviceSpecOf(const task::DeviceProfileDef& profile);
// `base` with the profile's rate limit, workspace box and continuous rating.
haptics::SafetyDef safetyOf(const task::DeviceProfileDef& profile, haptics::SafetyDef base = {});

// "" when the profile renders `coupling` (and its stiffest direction: M3's
// alpha scales the normal gain); else one sentence naming the level and the
// device: "level.lua asks for a coupling stiffness of 1500 N/m, above the
// 3D Systems Touch's maximum stiffness of 1020 N/m (devices/touch.lua)".
std::string couplingRefusal(const task::DeviceProfileDef& profile, const physics::CouplingDef& coupling,
                            const std::string& level);

}  // namespace hemiroll::game
