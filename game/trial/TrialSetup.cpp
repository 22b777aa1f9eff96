#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

haptics::DeviceSpec botDeviceSpec() {
  haptics::DeviceSpec spec;
  spec.name = "bot";
  return spec;
}

haptics::ServoLoopDef trialLoopDef(const task::LevelDef& level, const std::string& device) {
  haptics::ServoLoopDef def;
  def.requestRealtime = false;  // callers that start the loop's thread ask for it
  def.params = level.params;
  def.coupling = level.coupling;
  const task::DeviceMappingDef& mapping = level.mappingFor(device);
  def.mapping.scale = mapping.scale;
  def.mapping.offset = physics::Vec3(mapping.offset[0], mapping.offset[1], mapping.offset[2]);
  for (int i = 0; i < 12; ++i) def.initialState[static_cast<std::size_t>(i)] = level.initial[i];
  return def;
}

script::BotLevelInfo botLevelInfo(const task::LevelDef& level) { return botLevelInfo(level, trialLoopDef(level)); }

script::BotLevelInfo botLevelInfo(const task::LevelDef& level, const haptics::ServoLoopDef& def,
                                  const haptics::DeviceSpec& device) {
  script::BotLevelInfo info;
  info.name = level.name;
  info.file = level.source;
  info.params = level.params;
  info.coupling = level.coupling;
  info.dt = def.period;
  info.timeLimit = level.task.timeLimit;
  info.engageDistance = def.safety.engagement.engageDistance;
  info.workspaceRadius = device.workspaceRadius * def.mapping.scale;
  info.workspaceCentre = {def.mapping.offset.x(), def.mapping.offset.y(), def.mapping.offset.z()};
  return info;
}

}  // namespace hemiroll::game
