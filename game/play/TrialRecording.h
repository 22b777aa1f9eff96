#pragma once
// `hemiroll run --record DIR`: one trial recorded through engine/record.
// DIR becomes a recording session (created if needed): the trial's samples
// go to DIR/<trial>.csv with its sidecar DIR/<trial>.json (TrialRecorder,
// fed from the servo loop's record ring), and one summary row is appended
// to DIR/results.csv when the trial ends. The trial id is
// "<level file stem>_<bot file stem>_seed<N>", with "-2", "-3", ... added
// when DIR already holds a trial of that name (a rerun never overwrites).

#include <memory>
#include <stdexcept>
#include <string>

#include "engine/haptics/RecordRow.h"
#include "engine/script/LevelDef.h"
#include "game/commands/RunOptions.h"
#include "game/play/HeadlessTrial.h"

namespace hemiroll::record {
class RecordingSession;
class TrialRecorder;
}  // namespace hemiroll::record

namespace hemiroll::game {

// Any failure to create or write the recording, naming the file.
class TrialRecordingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class TrialRecording {
 public:
  // Opens the session and the trial's files, and points `settings` at the
  // ring and the drain. Throws TrialRecordingError.
  TrialRecording(const std::string& dir, const script::LevelDef& level, const RunOptions& options,
                 TrialSettings& settings);
  ~TrialRecording();
  TrialRecording(const TrialRecording&) = delete;
  TrialRecording& operator=(const TrialRecording&) = delete;

  // Completes the sidecar and appends the results row. Throws TrialRecordingError.
  void finish(const TrialResult& result);

  const std::string& trialId() const { return trialId_; }

 private:
  std::unique_ptr<haptics::RecordRing> ring_;  // 1 MB: on the heap, allocated once
  std::unique_ptr<record::RecordingSession> session_;
  std::unique_ptr<record::TrialRecorder> recorder_;
  std::string trialId_;
  std::string botPath_;
};

}  // namespace hemiroll::game
