#pragma once
// Loads a trial back (CSV + sidecar): for analysis tools and round-trip
// tests. Anything wrong with either file is a RecordError naming the file
// and, for the CSV, the line and column.
//
// An interrupted recording (kill -9, power loss) ends in the middle of a line
// and its sidecar says "complete": false. With allowTruncatedTail the reader
// keeps every complete line, drops the partial last one and says so;
// without it, such a file is an error.

#include <filesystem>
#include <functional>
#include <vector>

#include "engine/haptics/RecordRow.h"
#include "engine/record/Sidecar.h"
#include "engine/record/TrialMeta.h"

namespace hemiroll::record {

struct Recording {
  TrialMeta meta;
  SidecarStatus status;
  std::vector<haptics::RecordRow> rows;
  bool truncatedTail = false;  // a partial last line was dropped
};

struct ReadOptions {
  bool allowTruncatedTail = false;
};

class RecordingReader {
 public:
  // csvPath is <trial>.csv; the sidecar is the same path with .json.
  static Recording load(const std::filesystem::path& csvPath, const ReadOptions& options = {});
  static std::vector<haptics::RecordRow> loadCsv(const std::filesystem::path& csvPath, const ReadOptions& options,
                                                 bool* truncatedTail = nullptr);
  // The CSV's rows one at a time, read as a stream (a recording of a day
  // need not fit in memory as rows): `row` gets each parsed row. The file is
  // read through the checked reader (files::kSampleTable); a line longer
  // than kMaxLineBytes is refused. Returns whether a cut-off last line was
  // dropped (only with allowTruncatedTail; an error otherwise).
  static bool forEachRow(const std::filesystem::path& csvPath, const ReadOptions& options,
                         const std::function<void(const haptics::RecordRow&)>& row);
  // The sidecar beside `csvPath` (files::kSidecar).
  static void loadSidecar(const std::filesystem::path& csvPath, TrialMeta& meta, SidecarStatus& status);
  // A row is about 1.2 kB (45 shortest round-trip numbers); ten times that.
  static constexpr std::size_t kMaxLineBytes = 16 * 1024;
};

}  // namespace hemiroll::record
