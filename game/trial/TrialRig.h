#pragma once
// One trial put together in one place, whoever plays it: the servo loop's
// definition (built once, from the level), the device the loop reads, the
// loop, the judge (TrialJudge) and the one record tap. Bots (BotTrial) and
// a person in the window (PlaySession) differ only in the device they hand
// the rig and in which driver runs it:
//
//   stepping (headless)  step(): one tick on the calling thread, its
//                        snapshot judged and tapped; no thread, no clock,
//                        bit for bit the same for the same inputs;
//   threaded             startLoop(): the loop on its own thread at 1 kHz
//                        pushes a row of every tick into the rig's ring;
//                        drain(), once per bot period or per frame, judges
//                        every row the ring holds (none skipped) and taps it.
//
// The record tap is the one way rows reach a recording: a row is kept when
// the judge has judged it and its tick is a multiple of the tap's `every`
// (the recording's rate, TrialRecording). The recording's writer thread
// alone writes the rows; the stepping driver waits for room in its ring (a
// headless recording loses no row), a threaded one cannot wait (a frame, a
// bot period) and counts a row the full ring refused (tapLost()).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "engine/haptics/Guidance.h"
#include "engine/haptics/HapticDevice.h"
#include "engine/haptics/RecordRow.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/script/LevelLoader.h"
#include "game/trial/TrialJudge.h"

namespace hemiroll::game {

class ReplayCapture;

// Ticks a device without force output catches up after a stall (100 ms at
// 1 kHz, a few ms of CPU); a longer stall slows the clock by the rest. A
// device that renders force keeps the loop's default: a late tick stops it.
inline constexpr int kForcelessCatchUpTicks = 100;

// Where a trial's kept rows go: a recording's ring, one row every `every`
// judged ticks. No ring: nothing is kept.
struct RecordTap {
  haptics::RecordRing* ring = nullptr;
  int every = 1;
};

struct TrialRigDef {
  // Whose workspace mapping of the level the loop uses (task::kMappedDevices).
  std::string device = "bot";
  std::optional<physics::CouplingDef> coupling;  // none: the level's
  std::optional<haptics::SafetyDef> safety;      // none: the loop's defaults
  haptics::GuidanceDef guidance;                 // none by default
  // The threaded driver (startLoop/drain) instead of the stepping one (step).
  bool threaded = false;
  bool requestRealtime = false;          // threaded: SCHED_FIFO for the servo thread when permitted
  haptics::ServoClock* clock = nullptr;  // threaded: the servo thread's clock; null = the real one
  // A bot's trial ends at a safety fault; a person's goes on (the game
  // pauses and names it).
  bool faultsEndTrial = true;
  // Threaded: log every tick's input for a replay here ("" = none);
  // levelHash goes into its header. A log that cannot be created leaves the
  // trial without one (replayError() says why).
  std::filesystem::path replayFile;
  std::string levelHash;
};

// Makes the device the loop reads, for the loop's definition (its mapping
// and period). The rig owns what it returns. Throws what the device throws.
using RigDeviceMaker = std::function<std::unique_ptr<haptics::HapticDevice>(const haptics::ServoLoopDef&)>;

class TrialRig {
 public:
  // `level` must outlive the rig. Throws std::invalid_argument for a level
  // the loop refuses (its message names the field), and whatever
  // `makeDevice` throws.
  TrialRig(script::LoadedLevel& level, const TrialRigDef& def, const RigDeviceMaker& makeDevice);
  // Stops the loop's thread, then closes the device (on this thread).
  ~TrialRig();
  TrialRig(const TrialRig&) = delete;
  TrialRig& operator=(const TrialRig&) = delete;

  // Before the first tick: the recording's tap (TrialRecording::tap).
  void record(const RecordTap& tap);

  script::LoadedLevel& level() { return level_; }
  const haptics::ServoLoopDef& loopDef() const { return loopDef_; }
  haptics::ServoLoop& loop() { return *loop_; }
  const haptics::ServoLoop& loop() const { return *loop_; }
  haptics::HapticDevice& device() { return *device_; }
  const haptics::HapticDevice& device() const { return *device_; }
  TrialJudge& judging() { return judging_; }
  const TrialJudge& judging() const { return judging_; }
  const physics::ForceDrivenState& initial() const { return initial_; }
  // The latest tick the rig has taken from the loop (the initial state
  // before the first).
  const haptics::ServoSnapshot& snapshot() const { return snapshot_; }

  // A command for the loop (a full command ring drops it).
  void post(haptics::ServoCommandKind kind);

  // Stepping driver: one tick on this thread, judged and tapped.
  void step();

  // Threaded driver. startLoop starts the replay log, then the loop's
  // thread; stopLoop (idempotent) stops it, takes its last tick and
  // completes the replay log.
  void startLoop();
  void stopLoop();
  bool stopped() const { return stopped_; }
  // Judges and taps every row the loop has pushed since the last call; a
  // loop that dropped rows (the judge fell behind) fails the trial. Returns
  // the rows judged.
  std::size_t drain();
  // The loop's latest tick into snapshot(); false when it has none newer.
  bool takeLatest() { return loop_->latest(snapshot_); }

  // The judge's result (wallTime is left to the driver).
  TrialResult result() {
    TrialResult r = judging_.result(initial_);
    r.recordRowsLost = tapLost_;
    return r;
  }
  // Rows the tap's ring refused (threaded drivers only).
  std::uint64_t tapLost() const { return tapLost_; }
  // After stopLoop(): the replay log when one was asked for and came out
  // usable, else "" (replayError() says why).
  std::filesystem::path replayFile() const;
  const std::string& replayError() const { return replayError_; }

 private:
  void keep(const haptics::RecordRow& row);

  script::LoadedLevel& level_;
  TrialRigDef def_;
  haptics::ServoLoopDef loopDef_;
  // Threaded: every tick, for the judge. 4096 rows let a frame take up to
  // ~4 s (a dragged window, a hitch) before the judge falls behind.
  std::unique_ptr<haptics::RecordRing> judgeRing_;
  std::unique_ptr<ReplayCapture> capture_;
  std::string replayError_;
  std::unique_ptr<haptics::HapticDevice> device_;
  std::unique_ptr<haptics::ServoLoop> loop_;  // after device_: destroyed before it
  TrialJudge judging_;
  physics::ForceDrivenState initial_;
  haptics::ServoSnapshot snapshot_;
  RecordTap tap_;
  std::uint64_t tapLost_ = 0;
  bool stopped_ = false;
};

}  // namespace hemiroll::game
