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

// One record of RFC 4180 text from `at`: its fields, and `at` moved past its
// line end. False when the text ends before the line end.
bool readRecord(const std::string& text, std::size_t& at, std::vector<std::string>& fields, int& line) {
  fields.assign(1, std::string());
  bool quoted = false;
  while (at < text.size()) {
    const char c = text[at++];
    if (quoted) {
      if (c != '"') {
        line += c == '\n';
        fields.back() += c;
      } else if (at < text.size() && text[at] == '"') {
        fields.back() += '"';
        ++at;
      } else {
        quoted = false;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c == '\n') {
      ++line;
      return true;
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return false;
}

}  // namespace

std::optional<std::vector<std::string>> parseCsvLine(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t at = 0;
  int lineNumber = 1;
  if (!readRecord(line, at, fields, lineNumber) || at != line.size()) return std::nullopt;
  return fields;
}

ResultsTable ResultsFile::read() const {
  ResultsTable table;
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) return table;
  // A folder (or a device) in its place reads as empty: a resume would take
  // every finished trial for an interrupted one and move it aside.
  if (!std::filesystem::is_regular_file(path_, ec))
    throw RecordError(path_.string() + ": not a regular file; move it away and run again");
  const std::string text = readWholeFile(path_);
  std::size_t at = 0;
  int line = 1;
  std::vector<std::string> fields;
  while (at < text.size()) {
    const int first = line;
    if (!readRecord(text, at, fields, line))
      throw RecordError(path_.string() + ": line " + std::to_string(first) +
                        ": the last row has no line end (a write was cut short)");
    if (table.columns.empty()) {
      table.columns = fields;
    } else if (fields.size() != table.columns.size()) {
      throw RecordError(path_.string() + ": line " + std::to_string(first) + ": " + std::to_string(fields.size()) +
                        " fields, the header has " + std::to_string(table.columns.size()));
    } else {
      table.rows.push_back(fields);
    }
  }
  return table;
}

std::vector<std::string> ResultsFile::columns(const TrialResult& r) {
  std::vector<std::string> c = {"participant", "session", "trial",     "level",        "level_hash",
                                "outcome",     "reason",  "duration_s", "score",       "rows",
                                "dropped_rows", "start_time"};
  for (const auto& [key, value] : r.extra) c.push_back(key);
  return c;
}

void ResultsFile::checkColumns(const TrialResult& r) const {
  const std::string header = csvLine(columns(r));
  std::error_code ec;
  if (std::filesystem::exists(path_, ec) && !std::filesystem::is_regular_file(path_, ec))
    throw RecordError(path_.string() + ": not a regular file; move it away and run again");
  if (!std::filesystem::exists(path_, ec) || std::filesystem::file_size(path_, ec) == 0) return;
  // The header already there must be this row's: a session resumed with
  // other extra columns would otherwise misalign every later row.
  const std::string existing = readWholeFile(path_);
  if (existing.compare(0, header.size(), header) != 0)
    throw RecordError(path_.string() + ": line 1: the header differs from this result's columns (" +
                      header.substr(0, header.size() - 1) + ")");
}

void ResultsFile::append(const TrialResult& r) const {
  const std::string header = csvLine(columns(r));
  checkColumns(r);
  std::error_code ec;
  const bool fresh = !std::filesystem::exists(path_, ec) || std::filesystem::file_size(path_, ec) == 0;
  std::vector<std::string> fields = {r.participant, r.session,      r.trialId, r.level,
                                     r.levelHash,   r.outcome,      r.reason,  number(r.duration),
                                     number(r.score), std::to_string(r.rows), std::to_string(r.droppedRows),
                                     r.startTime};
  for (const auto& [key, value] : r.extra) fields.push_back(value);
  appendDurably(path_, (fresh ? header : std::string()) + csvLine(fields));
}

}  // namespace hemiroll::record
