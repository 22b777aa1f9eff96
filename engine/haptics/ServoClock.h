#pragma once
// The loop's notion of wall time, behind an interface so that the catch-up
// policy can be tested with a fake clock that jumps (tests/haptics).
// Times are nanoseconds on a monotonic clock.

#include <cstdint>

namespace hemiroll::haptics {

class ServoClock {
 public:
  virtual ~ServoClock() = default;
  virtual std::int64_t now() = 0;
  // Returns at or after the deadline (never before it).
  virtual void waitUntil(std::int64_t deadline) = 0;
};

// CLOCK_MONOTONIC: an absolute clock_nanosleep until spinMargin before the
// deadline (the kernel's wake-up latency is mostly below it), then a spin on
// the clock to the deadline itself. Absolute sleeps do not accumulate drift.
class SteadyServoClock final : public ServoClock {
 public:
  explicit SteadyServoClock(std::int64_t spinMarginNs = 50'000) : spinMargin_(spinMarginNs) {}
  std::int64_t now() override;
  void waitUntil(std::int64_t deadline) override;

 private:
  std::int64_t spinMargin_;
};

}  // namespace hemiroll::haptics
