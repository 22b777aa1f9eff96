#include "game/trial/ReplayPlayer.h"

#include <stdexcept>

#include "engine/haptics/devices/DeviceFactory.h"
#include "engine/record/ContentHash.h"
#include "game/trial/HeadlessTrial.h"
#include "game/trial/ReplayCapture.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

ReplayPlayer::ReplayPlayer(const script::LevelDef& level, const std::string& levelPath,
                           const std::filesystem::path& file)
    : log_(record::ReplayReader::load(file)) {
  if (log_.header.levelHash != record::fileContentHash(levelPath))
    throw std::runtime_error(file.string() + " was recorded on another version of " + levelPath);
  const std::string& kind = log_.header.deviceKind;
  const std::optional<haptics::DeviceSpec> spec = haptics::DeviceFactory().specOf(kind);
  if (!spec) throw std::runtime_error(file.string() + " was played with a device this program does not know: '" + kind + "'");
  haptics::ServoLoopDef def = trialLoopDef(level, kind);
  def.period = log_.header.dt;
  // The played device's spec: the safety layer clamps to it, as it did.
  device_ = std::make_unique<haptics::ReplayDevice>(log_.inputs, *spec);
  loop_ = std::make_unique<haptics::ServoLoop>(def, *device_);
  snapshot_.state = def.initialState;
}

ReplayPlayer::~ReplayPlayer() = default;

void ReplayPlayer::playTo(std::uint64_t ticks) {
  const std::size_t due = static_cast<std::size_t>(std::min<std::uint64_t>(ticks, log_.inputs.size()));
  if (next_ >= due) return;
  for (; next_ < due; ++next_) {
    const haptics::TickInput& in = log_.inputs[next_];
    for (; nextCommand_ < log_.commands.size() && log_.commands[nextCommand_].tick == in.tick; ++nextCommand_)
      loop_->post(log_.commands[nextCommand_].command);
    loop_->tick(in.latenessNs);
  }
  loop_->latest(snapshot_);
}

}  // namespace hemiroll::game
