#include "engine/haptics/ServoClock.h"

#include <cerrno>
#include <ctime>

namespace hemiroll::haptics {

std::int64_t SteadyServoClock::now() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

void SteadyServoClock::waitUntil(std::int64_t deadline) {
  const std::int64_t wake = deadline - spinMargin_;
  if (now() < wake) {
    timespec ts{};
    ts.tv_sec = static_cast<time_t>(wake / 1'000'000'000);
    ts.tv_nsec = static_cast<long>(wake % 1'000'000'000);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
    }
  }
  while (now() < deadline) {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();  // tells the core (and a hyper-thread sibling) that this is a spin
#endif
  }
}

}  // namespace hemiroll::haptics
