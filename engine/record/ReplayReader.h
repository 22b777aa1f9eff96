#pragma once
// Loads a replay log (ReplayFormat.h) for ReplayDevice. A file that is not a
// replay, has another format version, is truncated, was never finished, or
// whose records fail the checksum, skip a tick or hold an unknown command, is
// a RecordError naming the file and the byte offset or record.

#include <filesystem>
#include <vector>

#include "engine/files/CheckedFile.h"
#include "engine/haptics/RecordRow.h"
#include "engine/record/ReplayFormat.h"

namespace hemiroll::record {

struct ReplayLog {
  ReplayHeader header;
  std::vector<haptics::TickInput> inputs;
  std::vector<haptics::AppliedCommand> commands;  // in the order applied
};

class ReplayReader {
 public:
  // Read through the checked reader (files::kReplayLog).
  static ReplayLog load(const std::filesystem::path& path);
  static ReplayLog load(files::CheckedFile& file);
};

}  // namespace hemiroll::record
