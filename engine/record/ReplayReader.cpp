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
  if (body % kReplayRecordSize != 0 || body / kReplayRecordSize != h.tickCount)
    throw RecordError(where + "truncated or padded: the header announces " + std::to_string(h.tickCount) +
                      " records, the file holds " + std::to_string(body) + " bytes of records (" +
                      std::to_string(kReplayRecordSize) + " each)");
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
  return log;
}

}  // namespace hemiroll::record
