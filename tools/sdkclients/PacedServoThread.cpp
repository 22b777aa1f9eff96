#include "tools/sdkclients/PacedServoThread.h"

#include "engine/haptics/ServoClock.h"

namespace hemiroll::sdkclients {

void PacedServoThread::start(std::int64_t periodNs, std::function<void(std::int64_t)> step) {
  stop();
  running_.store(true);
  thread_ = std::thread([this, periodNs, step = std::move(step)] {
    haptics::SteadyServoClock clock;
    std::int64_t deadline = clock.now();
    while (running_.load(std::memory_order_relaxed)) {
      step(clock.now());
      deadline += periodNs;
      clock.waitUntil(deadline);
    }
  });
}

void PacedServoThread::stop() {
  running_.store(false);
  if (thread_.joinable()) thread_.join();
}

}  // namespace hemiroll::sdkclients
