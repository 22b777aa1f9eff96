#include "game/play/TrialRecording.h"

#include <cmath>
#include <filesystem>

#include "engine/record/RecordError.h"
#include "engine/record/RecordingSession.h"
#include "engine/record/TrialRecorder.h"

namespace hemiroll::game {

namespace {

// Letters, digits, '-', '_' and '.' only (TrialMeta's rule for file names).
std::string safeName(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
    out += ok ? c : '_';
  }
  return out.empty() ? "trial" : out;
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

std::string freshTrialId(const std::filesystem::path& dir, const std::string& base) {
  std::string id = base;
  for (int n = 2; std::filesystem::exists(dir / (id + ".csv")) || std::filesystem::exists(dir / (id + ".json")); ++n)
    id = base + "-" + std::to_string(n);
  return id;
}

}  // namespace

TrialRecording::TrialRecording(const std::string& dir, const script::LevelDef& level, const RunOptions& options,
                               TrialSettings& settings)
    : ring_(std::make_unique<haptics::RecordRing>()), botPath_(options.botPath) {
  const haptics::ServoLoopDef loop = HeadlessTrial::loopDefFor(level);
  // The level's recording rate, as a whole number of ticks per row.
  const int every = std::max(1, static_cast<int>(std::lround(1.0 / (level.scene.recordRate * loop.period))));
  try {
    session_ = std::make_unique<record::RecordingSession>(dir, record::SessionIds{"bot", "run"});
    record::TrialMeta meta;
    trialId_ = freshTrialId(dir, safeName(stem(options.levelPath)) + "_" + safeName(stem(options.botPath)) + "_seed" +
                                     std::to_string(options.seed));
    meta.trialId = trialId_;
    meta.taskName = "hemiroll run";
    meta.levelName = level.name;
    meta.seed = options.seed;
    meta.params = level.params;
    meta.coupling = level.coupling;
    meta.deviceName = "bot";
    meta.deviceSpec = HeadlessTrial::deviceSpec();
    meta.tickPeriod = loop.period;
    meta.recordEvery = every;
    meta.extra = {{"level_file", options.levelPath}, {"bot_file", options.botPath},
                  {"realtime", options.realtime ? "true" : "false"}};
    recorder_ = std::make_unique<record::TrialRecorder>(session_->beginTrial(meta));
  } catch (const record::RecordError& e) {
    throw TrialRecordingError(e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    throw TrialRecordingError(dir + ": " + e.what());
  }
  settings.recordRing = ring_.get();
  settings.recordEvery = every;
  settings.drainRecording = [this] { recorder_->drain(*ring_); };
}

TrialRecording::~TrialRecording() = default;

void TrialRecording::finish(const TrialResult& result) {
  record::TrialEnd end;
  end.outcome = result.outcome == script::TrialOutcome::Success ? "success" : "fail";
  end.reason = result.reason;
  try {
    recorder_->finish(end);
    record::TrialResult row = record::RecordingSession::resultOf(*recorder_, end, result.time);
    // results.csv has a number column for the score; an undefined score
    // (no score function) is 0 there and marked by has_score = false.
    const bool hasScore = result.score && std::isfinite(*result.score);
    row.score = hasScore ? *result.score : 0.0;
    row.extra = {{"has_score", hasScore ? "true" : "false"},
                 {"medal", script::medalName(result.medal)},
                 {"bot_file", botPath_},
                 {"ticks", std::to_string(result.ticks)}};
    session_->appendResult(row);
  } catch (const record::RecordError& e) {
    throw TrialRecordingError(e.what());
  }
}

}  // namespace hemiroll::game
