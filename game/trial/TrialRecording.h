#pragma once
// One trial recorded through engine/record, for `hemiroll run --record DIR`,
// `hemiroll session` and the game's research sessions: the rows the trial's
// rig taps (TrialRig::record(tap())) go through a ring to a TrialRecorder
// (DIR/<trial>.csv + sidecar DIR/<trial>.json), and one summary row is
// appended to DIR/results.csv when the trial ends. How often a row is kept
// is decided here once (the level's record rate), and the recorder's writer
// thread is the one writer of the rows, whoever plays the trial.

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "engine/haptics/RecordRow.h"
#include "engine/record/RecordingSession.h"
#include "engine/task/LevelDef.h"
#include "game/trial/TrialRig.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::record {
class TrialRecorder;
}  // namespace hemiroll::record

namespace hemiroll::game {

// Any failure to create or write the recording, naming the file.
class TrialRecordingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct TrialRecordingDef {
  std::string dir;                  // the session folder (created if needed)
  record::SessionIds ids;           // participant and session
  std::string trialId;              // names the files: letters, digits, '-', '_', '.'
  // Add "-2", "-3", ... while the id's files exist (a rerun of `hemiroll run`
  // never overwrites); otherwise existing files are an error.
  bool renameIfTaken = false;
  std::string taskName = "hemiroll";
  std::string levelHash;            // record::fileContentHash of the level file
  std::uint64_t seed = 0;
  std::string deviceName = "bot";
  haptics::DeviceSpec deviceSpec = botDeviceSpec();
  record::Fields sidecarExtra;      // the sidecar's `extra`
};

class TrialRecording {
 public:
  // Opens the session folder and the trial's files (the sidecar says
  // "complete": false until finish()) and starts the writer thread. `loop`
  // is the trial's servo loop definition (TrialRig::loopDef: its period,
  // coupling and guidance go into the sidecar); rows are kept at the
  // level's record rate. Throws TrialRecordingError.
  TrialRecording(const TrialRecordingDef& def, const task::LevelDef& level, const haptics::ServoLoopDef& loop);
  ~TrialRecording();
  TrialRecording(const TrialRecording&) = delete;
  TrialRecording& operator=(const TrialRecording&) = delete;

  // The ring the rows go through and every how many ticks one is kept: for
  // the trial's rig, before its first tick.
  RecordTap tap() { return {ring_.get(), recordEvery_}; }

  // Completes the sidecar (outcome, reason; the loop's timing for real-time
  // trials) and appends the results row with `extra` as its extra columns
  // (scoreFields() gives the usual has_score and medal). Throws TrialRecordingError.
  // `device`: how a device behind the bridge fared (the sidecar's outcome.device).
  void finish(const TrialResult& result, const record::Fields& extra,
              const std::optional<haptics::LoopTimingSummary>& timing = std::nullopt,
              const record::Fields& device = {});

  // has_score ("true"/"false": results.csv's score column is 0 when the
  // level has none) and medal.
  static record::Fields scoreFields(const TrialResult& result);
  // The trial's measures for results.csv, SI units in the column names:
  // stages passed and their times, path lengths, effort, smoothness, the
  // margins, and the end's error per task variable (RECORDING.md).
  static record::Fields measureFields(const TrialResult& result);

  const std::string& trialId() const { return trialId_; }
  const record::RecordingSession& session() const { return *session_; }

 private:
  std::unique_ptr<haptics::RecordRing> ring_;  // 1 MB: on the heap, allocated once
  std::unique_ptr<record::RecordingSession> session_;
  std::unique_ptr<record::TrialRecorder> recorder_;
  std::string trialId_;
  int recordEvery_ = 10;
};

}  // namespace hemiroll::game
