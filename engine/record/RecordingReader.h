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
};

}  // namespace hemiroll::record
