#include "engine/record/ResultsFile.h"

#include <system_error>

#include "engine/record/CsvRowFormat.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"

namespace hemiroll::record {

namespace {

std::string number(double v) {
  std::string s;
  appendDouble(v, s);
  return s;
}

}  // namespace

std::vector<std::string> ResultsFile::columns(const TrialResult& r) {
  std::vector<std::string> c = {"participant", "session", "trial",     "level",        "level_hash",
                                "outcome",     "reason",  "duration_s", "score",       "rows",
                                "dropped_rows", "start_time"};
  for (const auto& [key, value] : r.extra) c.push_back(key);
  return c;
}

void ResultsFile::append(const TrialResult& r) const {
  const std::string header = csvLine(columns(r));
  std::error_code ec;
  const bool fresh = !std::filesystem::exists(path_, ec) || std::filesystem::file_size(path_, ec) == 0;
  if (!fresh) {
    // The header already there must be this row's: a session resumed with
    // other extra columns would otherwise misalign every later row.
    const std::string existing = readWholeFile(path_);
    if (existing.compare(0, header.size(), header) != 0)
      throw RecordError(path_.string() + ": line 1: the header differs from this result's columns (" +
                        header.substr(0, header.size() - 1) + ")");
  }
  std::vector<std::string> fields = {r.participant, r.session,      r.trialId, r.level,
                                     r.levelHash,   r.outcome,      r.reason,  number(r.duration),
                                     number(r.score), std::to_string(r.rows), std::to_string(r.droppedRows),
                                     r.startTime};
  for (const auto& [key, value] : r.extra) fields.push_back(value);
  appendDurably(path_, (fresh ? header : std::string()) + csvLine(fields));
}

}  // namespace hemiroll::record
