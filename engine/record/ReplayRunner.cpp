#include "engine/record/ReplayRunner.h"

#include <algorithm>

#include "engine/record/RecordError.h"

namespace hemiroll::record {

bool ReplayCursor::playTo(haptics::ServoLoop& loop, const ReplayLog& log, std::size_t due) {
  due = std::min(due, log.inputs.size());
  bool accepted = true;
  for (; nextInput_ < due; ++nextInput_) {
    const haptics::TickInput& in = log.inputs[nextInput_];
    for (; nextCommand_ < log.commands.size() && log.commands[nextCommand_].tick == in.tick; ++nextCommand_)
      accepted = loop.post(log.commands[nextCommand_].command) && accepted;
    loop.tick(in.latenessNs);
  }
  return accepted;
}

std::uint64_t ReplayRunner::run(haptics::ServoLoop& loop, const ReplayLog& log) {
  ReplayCursor cursor;
  // One tick at a time, so that a refused command is named by its tick.
  for (std::size_t i = 0; i < log.inputs.size(); ++i)
    if (!cursor.playTo(loop, log, i + 1))
      throw RecordError("replay: the loop refused the command logged at tick " + std::to_string(log.inputs[i].tick) +
                        " (is it built from the logged level?)");
  return log.inputs.size();
}

}  // namespace hemiroll::record
