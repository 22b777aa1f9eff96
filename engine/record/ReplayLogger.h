#pragma once
// Writes a replay log (ReplayFormat.h): the device reading of every tick,
// taken from the servo loop's InputRing by a writer thread (or pushed by the
// calling thread in headless runs), so the tick itself only copies 64 bytes
// into a preallocated ring. finish() rewrites the header with the count, the
// checksum and the complete flag. Ticks must arrive consecutively: a gap (a
// full ring dropped inputs) makes the log unusable for a replay, and finish()
// says so (the file is then left without the complete flag).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "engine/haptics/RecordRow.h"
#include "engine/record/ReplayFormat.h"

namespace hemiroll::record {

class ReplayLogger {
 public:
  // header's tickCount, firstTick, checksum and flags are filled here. Throws
  // RecordError naming the file.
  ReplayLogger(const std::filesystem::path& path, const ReplayHeader& header, double pollInterval = 0.005);
  ~ReplayLogger();  // without finish(): the file stays incomplete
  ReplayLogger(ReplayLogger&&) noexcept;
  ReplayLogger& operator=(ReplayLogger&&) noexcept;

  void push(const haptics::TickInput& in);
  std::size_t drain(haptics::InputRing& ring);
  void startWriter(haptics::InputRing& ring);
  void stopWriter();
  // droppedInputs: ServoLoop::inputDropped(). Throws RecordError when the log
  // is unusable (inputs lost, a tick out of order, an I/O error).
  void finish(std::uint64_t droppedInputs = 0);

  std::uint64_t ticks() const;
  const std::filesystem::path& path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hemiroll::record
