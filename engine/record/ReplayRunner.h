#pragma once
// Runs a replay: ticks a ServoLoop headless once per logged input, posting
// each logged command just before the tick that applied it and giving each
// tick its logged lateness. With the loop built from the same definition
// (the level's, whose hash the log carries) and reading a ReplayDevice over
// log.inputs, every tick repeats the logged run bit for bit - a real-time
// run included, since nothing of the clock reaches the tick but lateness.

#include <cstdint>

#include "engine/haptics/ServoLoop.h"
#include "engine/record/ReplayReader.h"

namespace hemiroll::record {

class ReplayRunner {
 public:
  // Returns the ticks run (log.inputs.size()). Throws RecordError when the
  // loop refuses a logged command (a definition other than the logged run's).
  static std::uint64_t run(haptics::ServoLoop& loop, const ReplayLog& log);
};

}  // namespace hemiroll::record
