#pragma once
// Runs a replay: ticks a ServoLoop headless once per logged input, posting
// each logged command just before the tick that applied it and giving each
// tick its logged lateness. With the loop built from the same definition
// (the level's, whose hash the log carries) and reading a ReplayDevice over
// log.inputs, every tick repeats the logged run bit for bit - a real-time
// run included, since nothing of the clock reaches the tick but lateness.

#include <cstdint>
#include <optional>

#include "engine/haptics/ServoLoop.h"
#include "engine/record/ReplayReader.h"

namespace hemiroll::record {

class ReplayRunner {
 public:
  // Returns the ticks run (log.inputs.size()). Throws RecordError when the
  // loop refuses a logged command (a definition other than the logged run's).
  static std::uint64_t run(haptics::ServoLoop& loop, const ReplayLog& log);
};

// Where a replay has got to, for playing it a part at a time (the replay
// screen, a ghost): the same posting-then-ticking rule as ReplayRunner.
class ReplayCursor {
 public:
  // Plays the log's inputs up to (not including) index `due`, or its end.
  // Returns the tick of the first logged command the loop refused, having
  // played on; nothing if it took them all.
  std::optional<std::uint64_t> playTo(haptics::ServoLoop& loop, const ReplayLog& log, std::size_t due);
  std::size_t next() const { return nextInput_; }

 private:
  std::size_t nextInput_ = 0, nextCommand_ = 0;
};

}  // namespace hemiroll::record
