#pragma once
// The session's results.csv: one summary row per finished trial, appended
// with a single write() and fsync'ed, the header written once when the file
// is new. A row's extra keys become columns; every later row must bring the
// same keys (checked against the header already in the file, so a resumed
// session appends consistently). Text is quoted as RFC 4180 says.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/files/FileKinds.h"
#include "engine/record/TrialMeta.h"

namespace hemiroll::record {

// One row of results.csv (what the file keeps of a trial; the judge's
// verdict is game::TrialResult).
struct ResultsRow {
  std::string participant;
  std::string session;
  std::string trialId;
  std::string level;
  std::string levelHash;
  std::string outcome;        // "success", "failure", "aborted", ...
  std::string reason;
  double duration = 0.0;      // [s] of simulation time
  double score = 0.0;
  std::uint64_t rows = 0;
  std::uint64_t droppedRows = 0;
  std::string startTime;      // ISO-8601 UTC
  Fields extra;               // more columns, in this order
};

// results.csv read back: the header's columns and every row's fields.
struct ResultsTable {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
};

// The fields of one RFC 4180 record that is all of `line` (its line end
// included); nothing when it is not exactly one whole record.
std::optional<std::vector<std::string>> parseCsvLine(const std::string& line);

class ResultsFile {
 public:
  // `kind`: the cap on the file's size (results.csv, or a sweep's table,
  // which has the same format); it is read as a stream of records.
  explicit ResultsFile(std::filesystem::path path, const files::FileKind& kind = files::kResults)
      : path_(std::move(path)), kind_(kind) {}

  // Throws RecordError naming the file on an I/O error or a column mismatch.
  void append(const ResultsRow& result) const;
  // Throws RecordError when the file holds a header other than `result`'s
  // columns: what append() would refuse, asked before a trial is played
  // rather than after it.
  void checkColumns(const ResultsRow& result) const;
  const std::filesystem::path& path() const { return path_; }
  // The file's header and rows (RFC 4180: quoted fields may hold commas,
  // quotes and line breaks); a missing file is an empty table. Throws
  // RecordError naming the file and line for a row with more or fewer
  // fields than the header, or a last row without its line end (a write cut
  // short: appends are single writes, so only a power cut leaves one).
  ResultsTable read() const;
  // The same, one row at a time: `row` is called with each row's fields
  // (the header's are in `columns` by then) and may throw to stop. Memory
  // stays at one record, however long the file. A record longer than
  // kMaxRecordBytes is refused with its line.
  void forEachRow(std::vector<std::string>& columns,
                  const std::function<void(const std::vector<std::string>& fields, int line)>& row) const;
  static constexpr std::size_t kMaxRecordBytes = std::size_t{1} << 20;

  static std::vector<std::string> columns(const ResultsRow& result);

 private:
  std::filesystem::path path_;
  files::FileKind kind_;
};

}  // namespace hemiroll::record
