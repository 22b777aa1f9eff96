#include "engine/record/ReplayReader.h"

#include <algorithm>
#include <cstring>

#include "engine/files/FileReadError.h"
#include "engine/files/PrintableName.h"
#include "engine/record/RecordError.h"

namespace hemiroll::record {

namespace {

// Exactly `size` bytes from the file, or an error naming what is short.
void readExactly(files::CheckedFile& file, unsigned char* out, std::size_t size, const std::string& where) {
  std::size_t filled = 0;
  while (filled < size) {
    const std::size_t n = file.read(reinterpret_cast<char*>(out) + filled, size - filled);
    if (n == 0) throw RecordError(where + "the file ended early (it shrank while it was read)");
    filled += n;
  }
}

}  // namespace

ReplayLog ReplayReader::load(const std::filesystem::path& path) {
  try {
    files::CheckedFile file(path, files::kReplayLog);
    return load(file);
  } catch (const files::FileReadError& e) {
    throw RecordError(e.what());
  }
}

// Read as a stream: the header is checked first and the file's size against
// the counts it announces, so a file of zeros or of the wrong size costs
// one read; the body a chunk at a time, checksummed as it is decoded.
ReplayLog ReplayReader::load(files::CheckedFile& file) {
  const std::string where = files::printablePath(file.path()) + ": ";
  const std::uintmax_t size = file.size();
  if (size < kReplayHeaderSize)
    throw RecordError(where + "too short for a replay header (" + std::to_string(size) + " bytes, need " +
                      std::to_string(kReplayHeaderSize) + ")");
  ReplayLog log;
  ReplayHeaderBytes head;
  readExactly(file, head.data(), head.size(), where);
  const std::string problem = decodeReplayHeader(head, log.header);
  if (!problem.empty()) throw RecordError(where + problem);
  const ReplayHeader& h = log.header;
  if ((h.flags & kReplayComplete) == 0)
    throw RecordError(where + "the log was never finished (an interrupted run, or inputs were lost)");
  const std::uintmax_t body = size - kReplayHeaderSize;
  // Both counts are bounded by the file's size before they are multiplied.
  if (h.tickCount > body / kReplayRecordSize || h.commandCount > body / kReplayCommandSize ||
      h.tickCount * kReplayRecordSize + h.commandCount * kReplayCommandSize != body)
    throw RecordError(where + "truncated or padded: the header announces " + std::to_string(h.tickCount) +
                      " inputs of " + std::to_string(kReplayRecordSize) + " bytes and " +
                      std::to_string(h.commandCount) + " commands of " + std::to_string(kReplayCommandSize) +
                      " bytes, the file holds " + std::to_string(body) + " bytes after the header");
  std::uint64_t checksum = kFnvOffset;
  // Grown as records prove valid: a header may announce what the file's
  // garbage then does not hold.
  log.inputs.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(h.tickCount, 1u << 16)));
  ReplayRecordBytes rec;
  for (std::uint64_t k = 0; k < h.tickCount; ++k) {
    readExactly(file, rec.data(), rec.size(), where);
    checksum = fnv1a(rec.data(), rec.size(), checksum);
    const haptics::TickInput in = decodeReplayRecord(rec);
    if (in.tick != h.firstTick + k || rec[60] > 1)
      throw RecordError(where + "record " + std::to_string(k) + " (byte " +
                        std::to_string(kReplayHeaderSize + k * kReplayRecordSize) + "): tick " +
                        std::to_string(in.tick) + " out of sequence or bad flag byte");
    log.inputs.push_back(in);
  }
  ReplayCommandBytes command;
  for (std::uint64_t k = 0; k < h.commandCount; ++k) {
    readExactly(file, command.data(), command.size(), where);
    checksum = fnv1a(command.data(), command.size(), checksum);
    haptics::AppliedCommand c;
    std::string problem = decodeReplayCommand(command, c);
    if (problem.empty() && (c.tick < h.firstTick || c.tick >= h.firstTick + h.tickCount ||
                            (!log.commands.empty() && c.tick < log.commands.back().tick)))
      problem = "tick " + std::to_string(c.tick) + " out of order or outside the logged ticks";
    if (!problem.empty())
      throw RecordError(where + "command " + std::to_string(k) + " (byte " +
                        std::to_string(kReplayHeaderSize + h.tickCount * kReplayRecordSize + k * kReplayCommandSize) +
                        "): " + problem);
    log.commands.push_back(c);
  }
  if (checksum != h.checksum) throw RecordError(where + "the records fail the checksum (the file is corrupt)");
  return log;
}

}  // namespace hemiroll::record
