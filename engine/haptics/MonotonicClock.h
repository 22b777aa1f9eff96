#pragma once
// The devices' own notion of time (CLOCK_MONOTONIC, nanoseconds): watchdogs
// and velocity filters run on it rather than on the loop's simulation time,
// which stops while play is paused. A plain function pointer, so that tests
// can substitute a fake clock and the servo thread pays no indirection cost
// beyond one call.

#include <cstdint>
#include <ctime>

namespace hemiroll::haptics {

using MonotonicClock = std::int64_t (*)();

inline std::int64_t monotonicNowNs() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

}  // namespace hemiroll::haptics
