#include "engine/platform/FrameClock.h"

#include <algorithm>
#include <chrono>

namespace hemiroll::platform {

FrameClock::FrameClock(FrameClockDef def, TimeSource now) : def_(def), now_(std::move(now)) {
  if (!now_) {
    now_ = [] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    };
  }
}

double FrameClock::tick() {
  const double t = now_();
  ++frames_;
  if (frames_ == 1) {
    last_ = t;
    return 0.0;
  }
  const double raw = std::max(0.0, t - last_);  // a clock that steps back gives 0, never negative
  last_ = t;
  steps_[stepCount_ % kWindow] = raw;
  ++stepCount_;
  return std::min(raw, def_.maxStep);
}

double FrameClock::medianFps() const {
  const std::size_t n = std::min(stepCount_, kWindow);
  if (n == 0) return 0.0;
  // A copy on the stack: the HUD calls this every frame, and it must not allocate.
  std::array<double, kWindow> sorted = steps_;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.begin() + n);
  const double median = sorted[n / 2];
  return median > 0.0 ? 1.0 / median : 0.0;
}

}  // namespace hemiroll::platform
