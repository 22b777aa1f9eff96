#pragma once
// A session folder: trial files side by side and one results.csv.
//
//   <dir>/<trialId>.csv, <trialId>.json   per trial (TrialRecorder)
//   <dir>/<trialId>.replay                per trial, when logged (ReplayLogger)
//   <dir>/results.csv                     one row per finished trial

#include <filesystem>
#include <string>

#include "engine/record/ResultsFile.h"
#include "engine/record/TrialRecorder.h"

namespace hemiroll::record {

struct SessionIds {
  std::string participant = "anonymous";
  std::string session = "1";
};

class RecordingSession {
 public:
  // Creates dir (and its parents). Throws RecordError naming it when it cannot.
  RecordingSession(std::filesystem::path dir, SessionIds ids);

  // Fills meta's empty participant and session with the session's ids.
  TrialRecorder beginTrial(TrialMeta meta, const RecorderOptions& options = {}) const;
  // Fills the result's empty participant and session likewise.
  void appendResult(ResultsRow result) const;
  // A result row from a finished recorder's metadata; the caller adds score
  // and extras.
  static ResultsRow resultOf(const TrialRecorder& recorder, const TrialEnd& end, double duration);

  const std::filesystem::path& dir() const { return dir_; }
  const SessionIds& ids() const { return ids_; }
  std::filesystem::path resultsPath() const { return results_.path(); }
  std::filesystem::path replayPath(const std::string& trialId) const { return dir_ / (trialId + ".replay"); }

 private:
  std::filesystem::path dir_;
  SessionIds ids_;
  ResultsFile results_;
};

}  // namespace hemiroll::record
