#pragma once
// Paces the main thread's frames so that the window leaves the CPU to the
// 1 kHz servo thread (issue 27): on a 2-core machine a window drawing flat
// out (llvmpipe, ~100 fps) kept both cores busy and the servo loop starved.
//
// After each frame's swap, pace() sleeps until the frame's deadline, one
// interval (1 / fps) after the previous one. A frame that came late sets the
// next deadline from its own end: a late frame is never made up by frames
// drawn back to back. With vsync on a display that paces the swaps, a frame
// already ends on the display's beat and the deadline has passed by then:
// nothing is slept, so the two never fight (a cap below the refresh rate
// still holds).
//
// Time and sleep come from the caller, so tests drive it with a fake clock;
// the defaults are std::chrono::steady_clock and std::this_thread::sleep_for.

#include <functional>

namespace hemiroll::platform {

struct FramePacerDef {
  std::function<double()> now;             // monotonic seconds; {} = steady_clock
  std::function<void(double)> sleep;       // sleeps that many seconds; {} = sleep_for
};

class FramePacer {
 public:
  explicit FramePacer(FramePacerDef def = {});

  // Once per frame, after the swap. fps <= 0 (or not finite): no pacing.
  void pace(double fps);
  // What the last pace() slept [s] (0 when the frame was already late).
  double lastSleep() const { return lastSleep_; }
  // The total slept since construction [s]: the CPU handed back.
  double totalSleep() const { return totalSleep_; }

 private:
  FramePacerDef def_;
  double deadline_ = -1.0;  // the previous frame's end as paced [s]; < 0 before the first
  double lastSleep_ = 0.0, totalSleep_ = 0.0;
};

}  // namespace hemiroll::platform
