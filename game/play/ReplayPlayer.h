#pragma once
// Plays a replay log (engine/record) through a ServoLoop built from the
// level, on the caller's thread, as far as the caller asks: the recorded
// trial again, bit for bit, a frame's worth of ticks at a time. Each logged
// command is posted before the tick that applied it (record::ReplayCursor).
// In the play layer: it builds the played device's spec (DeviceFactory),
// which the headless toolkit may not link.
// Shared by the replay screen (1x speed) and the ghost that races beside
// live play (as far as the live trial has got).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "engine/haptics/devices/ReplayDevice.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/record/ReplayReader.h"
#include "engine/record/ReplayRunner.h"
#include "engine/task/LevelDef.h"

namespace hemiroll::game {

class ReplayPlayer {
 public:
  // `level` is the loaded level of `levelPath`. Throws std::runtime_error
  // with one sentence: the file cannot be read or is no complete replay, it
  // was recorded on another version of the level, or with a device this
  // program does not know.
  ReplayPlayer(const task::LevelDef& level, const std::string& levelPath, const std::filesystem::path& file);
  ~ReplayPlayer();

  // Plays ticks until `ticks` have been played or the log ends.
  void playTo(std::uint64_t ticks);
  // The state after the last tick played (the level's start before any).
  const haptics::ServoSnapshot& snapshot() const { return snapshot_; }
  std::uint64_t ticksPlayed() const { return cursor_.next(); }
  std::uint64_t ticksTotal() const { return log_.inputs.size(); }
  bool done() const { return cursor_.next() >= log_.inputs.size(); }
  double period() const { return log_.header.dt; }  // [s] per tick

 private:
  record::ReplayLog log_;
  std::unique_ptr<haptics::ReplayDevice> device_;
  std::unique_ptr<haptics::ServoLoop> loop_;
  record::ReplayCursor cursor_;
  haptics::ServoSnapshot snapshot_;
};

}  // namespace hemiroll::game
