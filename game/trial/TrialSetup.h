#pragma once
// How a level becomes a servo loop: the loop's definition (params, initial
// state, coupling, the device's workspace mapping), the desk device a bot is
// held to, and what a bot is told about the level. One place, so that a
// headless bot, `run --realtime`, a person in the window, a replay and a
// research session's recording all start from the same loop.

#include <string>

#include "engine/haptics/DeviceSpec.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/script/BotObservation.h"
#include "engine/task/LevelDef.h"

namespace hemiroll::game {

// The servo loop's definition for a level (default safety; no thread
// requested, no rings). `device` picks the level's workspace mapping
// (task::kMappedDevices).
haptics::ServoLoopDef trialLoopDef(const task::LevelDef& level, const std::string& device = "bot");

// A desk device's limits (DeviceSpec defaults), named "bot": what a bot is
// held to.
haptics::DeviceSpec botDeviceSpec();

// The level as a bot's init sees it, in the trial's loop (`loop`: built by
// trialLoopDef for "bot"; its period, engagement and mapping), held to
// the workspace of `device` (botDeviceSpec's unless a profile gave another).
script::BotLevelInfo botLevelInfo(const task::LevelDef& level, const haptics::ServoLoopDef& loop,
                                  const haptics::DeviceSpec& device = botDeviceSpec());
// The same for a planner beside a trial whose loop is not a bot's (the
// autopilot in the window plans in the level's bot loop).
script::BotLevelInfo botLevelInfo(const task::LevelDef& level);

}  // namespace hemiroll::game
