#include "game/play/ReplayPlayer.h"

#include <stdexcept>

#include "engine/haptics/devices/sdl/DeviceFactory.h"
#include "engine/record/ContentHash.h"
#include "game/trial/ReplayCapture.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

ReplayPlayer::ReplayPlayer(const task::LevelDef& level, const std::string& levelPath,
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
  if (cursor_.next() >= due) return;
  // A refused command cannot happen here: the level's hash was checked when
  // the log was opened, so the loop is the logged run's.
  cursor_.playTo(*loop_, log_, due);
  loop_->latest(snapshot_);
}

}  // namespace hemiroll::game
