#include "game/trial/TrialRecording.h"

#include <cmath>
#include <filesystem>

#include "engine/record/RecordError.h"
#include "engine/record/TrialRecorder.h"

namespace hemiroll::game {

namespace {

std::string freshTrialId(const std::filesystem::path& dir, const std::string& base) {
  std::string id = base;
  for (int n = 2; std::filesystem::exists(dir / (id + ".csv")) || std::filesystem::exists(dir / (id + ".json")); ++n)
    id = base + "-" + std::to_string(n);
  return id;
}

}  // namespace

TrialRecording::TrialRecording(const TrialRecordingDef& def, const task::LevelDef& level,
                               const haptics::ServoLoopDef& loop)
    : ring_(std::make_unique<haptics::RecordRing>()) {
  // The level's recording rate, as a whole number of ticks per row.
  recordEvery_ = std::max(1, static_cast<int>(std::lround(1.0 / (level.scene.recordRate * loop.period))));
  try {
    session_ = std::make_unique<record::RecordingSession>(def.dir, def.ids);
    record::TrialMeta meta;
    trialId_ = def.renameIfTaken ? freshTrialId(def.dir, def.trialId) : def.trialId;
    meta.trialId = trialId_;
    meta.taskName = def.taskName;
    meta.levelName = level.name;
    meta.levelHash = def.levelHash;
    meta.seed = def.seed;
    meta.params = level.params;
    meta.coupling = loop.coupling;
    meta.guidance = loop.guidance;
    meta.deviceName = def.deviceName;
    meta.deviceSpec = def.deviceSpec;
    meta.tickPeriod = loop.period;
    meta.recordEvery = recordEvery_;
    meta.extra = def.sidecarExtra;
    recorder_ = std::make_unique<record::TrialRecorder>(session_->beginTrial(meta));
  } catch (const record::RecordError& e) {
    throw TrialRecordingError(e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    throw TrialRecordingError(def.dir + ": " + e.what());
  }
  recorder_->startWriter(*ring_);  // until finish() (or the destructor)
}

TrialRecording::~TrialRecording() = default;

record::Fields TrialRecording::measureFields(const TrialResult& result) {
  const task::TrialSummary& s = result.summary;
  char text[64];
  const auto number = [&text](double v) {
    std::snprintf(text, sizeof text, "%.17g", v);
    return std::string(text);
  };
  std::string times;
  for (std::size_t i = 0; i < s.stageTimes.size(); ++i) {
    if (i > 0) times += ';';
    std::snprintf(text, sizeof text, "%.6f", s.stageTimes[i]);  // a tick's time, to the microsecond
    times += text;
  }
  record::Fields out = {{"stages_passed", std::to_string(s.stagesPassed)},
                        {"stage_count", std::to_string(s.stageCount)},
                        {"stage_times_s", times},
                        {"contact_path_m", number(s.contactPath)},
                        {"point_path_m", number(s.pointPath)},
                        {"effort_N2_s", number(s.effort)},
                        {"smoothness_m2_per_s6", number(s.smoothness)},
                        {"best_margin", number(s.bestMargin)},
                        {"final_margin", number(s.finalMargin)}};
  // The current stage's error per variable at the end, every variable in
  // one fixed set of columns (a session's levels judge different ones, and
  // every row of results.csv has the header's columns); empty where the
  // stage does not judge it.
  for (int v = 0; v < task::kTaskVariableCount; ++v) {
    const auto variable = static_cast<task::TaskVariable>(v);
    std::string value;
    for (const task::ComponentStatus& c : s.finalComponents)
      if (c.variable == variable) value = number(c.error);
    out.emplace_back(std::string("final_error_") + task::taskVariableName(variable) + "_" +
                         task::taskVariableUnitTag(variable),
                     value);
  }
  return out;
}

record::Fields TrialRecording::scoreFields(const TrialResult& result) {
  const bool hasScore = result.score && std::isfinite(*result.score);
  return {{"has_score", hasScore ? "true" : "false"}, {"medal", task::medalName(result.medal)}};
}

void TrialRecording::finish(const TrialResult& result, const record::Fields& extra,
                            const std::optional<haptics::LoopTimingSummary>& timing,
                            const record::Fields& device) {
  record::TrialEnd end;
  end.device = device;
  // The words of `run`'s JSON line and the judge: "success" or "failure".
  end.outcome = task::trialOutcomeName(result.outcome);
  end.reason = result.reason;
  end.droppedRows = result.recordRowsLost;
  end.hasTiming = timing.has_value();
  if (timing) end.timing = *timing;
  try {
    recorder_->finish(end);
    record::ResultsRow row = record::RecordingSession::resultOf(*recorder_, end, result.time);
    // results.csv has a number column for the score; an undefined score
    // (no score function) is 0 there and marked by has_score = false.
    const bool hasScore = result.score && std::isfinite(*result.score);
    row.score = hasScore ? *result.score : 0.0;
    row.extra = extra;
    session_->appendResult(row);
  } catch (const record::RecordError& e) {
    throw TrialRecordingError(e.what());
  }
}

}  // namespace hemiroll::game
