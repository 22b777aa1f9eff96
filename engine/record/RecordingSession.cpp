#include "engine/record/RecordingSession.h"

#include <system_error>
#include <utility>

#include "engine/record/RecordError.h"

namespace hemiroll::record {

RecordingSession::RecordingSession(std::filesystem::path dir, SessionIds ids)
    : dir_(std::move(dir)), ids_(std::move(ids)), results_(dir_ / "results.csv") {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec || !std::filesystem::is_directory(dir_))
    throw RecordError(dir_.string() + ": cannot create the session folder" + (ec ? ": " + ec.message() : ""));
}

TrialRecorder RecordingSession::beginTrial(TrialMeta meta, const RecorderOptions& options) const {
  if (meta.participant.empty()) meta.participant = ids_.participant;
  if (meta.session.empty()) meta.session = ids_.session;
  return TrialRecorder(dir_, meta, options);
}

void RecordingSession::appendResult(ResultsRow result) const {
  if (result.participant.empty()) result.participant = ids_.participant;
  if (result.session.empty()) result.session = ids_.session;
  results_.append(result);
}

ResultsRow RecordingSession::resultOf(const TrialRecorder& recorder, const TrialEnd& end, double duration) {
  const TrialMeta& m = recorder.meta();
  ResultsRow r;
  r.participant = m.participant;
  r.session = m.session;
  r.trialId = m.trialId;
  r.level = m.levelName;
  r.levelHash = m.levelHash;
  r.outcome = end.outcome;
  r.reason = end.reason;
  r.duration = duration;
  r.rows = recorder.rows();
  r.droppedRows = end.droppedRows;
  r.startTime = recorder.startTime();
  return r;
}

}  // namespace hemiroll::record
