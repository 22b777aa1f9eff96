#include "engine/record/ReplayRunner.h"

#include "engine/record/RecordError.h"

namespace hemiroll::record {

std::uint64_t ReplayRunner::run(haptics::ServoLoop& loop, const ReplayLog& log) {
  std::size_t next = 0;
  for (const haptics::TickInput& in : log.inputs) {
    for (; next < log.commands.size() && log.commands[next].tick == in.tick; ++next)
      if (!loop.post(log.commands[next].command))
        throw RecordError("replay: the loop refused the command logged at tick " + std::to_string(in.tick) +
                          " (is it built from the logged level?)");
    loop.tick(in.latenessNs);
  }
  return log.inputs.size();
}

}  // namespace hemiroll::record
