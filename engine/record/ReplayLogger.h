#pragma once
// Writes a replay log (ReplayFormat.h): the device reading and lateness of
// every tick and every command applied, taken from the servo loop's
// InputRing and CommandRing by a writer thread (or pushed by the calling
// thread in headless runs), so the tick itself only copies a few bytes into
// preallocated rings. Inputs stream to the file as they come; commands (a
// few per trial) are kept and written after them by finish(), which then
// rewrites the header with the counts, the checksum and the complete flag. Ticks must arrive consecutively: a gap (a
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
  void push(const haptics::AppliedCommand& command);
  // Pops and writes what the rings hold now; returns how many inputs.
  std::size_t drain(haptics::InputRing& inputs, haptics::CommandRing* commands = nullptr);
  void startWriter(haptics::InputRing& inputs, haptics::CommandRing* commands = nullptr);
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
