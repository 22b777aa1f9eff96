#include "engine/record/ReplayRunner.h"

#include <algorithm>

#include "engine/record/RecordError.h"

namespace hemiroll::record {

std::optional<std::uint64_t> ReplayCursor::playTo(haptics::ServoLoop& loop, const ReplayLog& log, std::size_t due) {
  due = std::min(due, log.inputs.size());
  std::optional<std::uint64_t> refused;
  for (; nextInput_ < due; ++nextInput_) {
    const haptics::TickInput& in = log.inputs[nextInput_];
    for (; nextCommand_ < log.commands.size() && log.commands[nextCommand_].tick == in.tick; ++nextCommand_)
      if (!loop.post(log.commands[nextCommand_].command) && !refused) refused = in.tick;
    loop.tick(in.latenessNs);
  }
  return refused;
}

std::uint64_t ReplayRunner::run(haptics::ServoLoop& loop, const ReplayLog& log) {
  if (const auto refused = ReplayCursor().playTo(loop, log, log.inputs.size()))
    throw RecordError("replay: the loop refused the command logged at tick " + std::to_string(*refused) +
                      " (is it built from the logged level?)");
  return log.inputs.size();
}

}  // namespace hemiroll::record
