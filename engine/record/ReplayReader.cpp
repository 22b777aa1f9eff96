#include "engine/record/ReplayReader.h"

#include <cstring>

#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"

namespace hemiroll::record {

ReplayLog ReplayReader::load(const std::filesystem::path& path) {
  const std::string bytes = readWholeFile(path);
  const std::string where = path.string() + ": ";
  if (bytes.size() < kReplayHeaderSize)
    throw RecordError(where + "too short for a replay header (" + std::to_string(bytes.size()) + " bytes, need " +
                      std::to_string(kReplayHeaderSize) + ")");
  ReplayLog log;
  ReplayHeaderBytes head;
  std::memcpy(head.data(), bytes.data(), head.size());
  const std::string problem = decodeReplayHeader(head, log.header);
  if (!problem.empty()) throw RecordError(where + problem);
  const ReplayHeader& h = log.header;
  if ((h.flags & kReplayComplete) == 0)
    throw RecordError(where + "the log was never finished (an interrupted run, or inputs were lost)");
  const std::size_t body = bytes.size() - kReplayHeaderSize;
  // Both counts are bounded by the file's size before they are multiplied.
  if (h.tickCount > body / kReplayRecordSize || h.commandCount > body / kReplayCommandSize ||
      h.tickCount * kReplayRecordSize + h.commandCount * kReplayCommandSize != body)
    throw RecordError(where + "truncated or padded: the header announces " + std::to_string(h.tickCount) +
                      " inputs of " + std::to_string(kReplayRecordSize) + " bytes and " +
                      std::to_string(h.commandCount) + " commands of " + std::to_string(kReplayCommandSize) +
                      " bytes, the file holds " + std::to_string(body) + " bytes after the header");
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data()) + kReplayHeaderSize;
  if (fnv1a(data, body, kFnvOffset) != h.checksum)
    throw RecordError(where + "the records fail the checksum (the file is corrupt)");
  log.inputs.reserve(h.tickCount);
  for (std::uint64_t k = 0; k < h.tickCount; ++k) {
    ReplayRecordBytes rec;
    std::memcpy(rec.data(), data + k * kReplayRecordSize, rec.size());
    const haptics::TickInput in = decodeReplayRecord(rec);
    if (in.tick != h.firstTick + k || rec[60] > 1)
      throw RecordError(where + "record " + std::to_string(k) + " (byte " +
                        std::to_string(kReplayHeaderSize + k * kReplayRecordSize) + "): tick " +
                        std::to_string(in.tick) + " out of sequence or bad flag byte");
    log.inputs.push_back(in);
  }
  const unsigned char* commands = data + h.tickCount * kReplayRecordSize;
  for (std::uint64_t k = 0; k < h.commandCount; ++k) {
    ReplayCommandBytes rec;
    std::memcpy(rec.data(), commands + k * kReplayCommandSize, rec.size());
    haptics::AppliedCommand c;
    std::string problem = decodeReplayCommand(rec, c);
    if (problem.empty() && (c.tick < h.firstTick || c.tick >= h.firstTick + h.tickCount ||
                            (!log.commands.empty() && c.tick < log.commands.back().tick)))
      problem = "tick " + std::to_string(c.tick) + " out of order or outside the logged ticks";
    if (!problem.empty())
      throw RecordError(where + "command " + std::to_string(k) + " (byte " +
                        std::to_string(kReplayHeaderSize + h.tickCount * kReplayRecordSize + k * kReplayCommandSize) +
                        "): " + problem);
    log.commands.push_back(c);
  }
  return log;
}

}  // namespace hemiroll::record
