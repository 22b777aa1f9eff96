#pragma once
// The main thread's frame clock: the time step of each frame (clamped, so a
// debugger pause or a dragged window does not make animations jump) and the
// median frame rate over the last frames (what the HUD's timing warning
// shows; the median, because single hitches are not the rate).
//
// Time comes from a caller-supplied source in seconds, so tests can drive it;
// the default is std::chrono::steady_clock.

#include <array>
#include <cstddef>
#include <functional>

namespace hemiroll::platform {

struct FrameClockDef {
  double maxStep = 0.1;  // the longest frame step handed out [s]: 10 fps worth
};

class FrameClock {
 public:
  using TimeSource = std::function<double()>;  // monotonic seconds
  explicit FrameClock(FrameClockDef def = {}, TimeSource now = {});

  // Call once per frame; returns the step since the previous call [s], in
  // [0, maxStep] (0 on the first call).
  double tick();
  // Median frames per second over the last kWindow frame steps (unclamped);
  // 0 before the first full step.
  double medianFps() const;
  std::size_t frames() const { return frames_; }

  static constexpr std::size_t kWindow = 61;

 private:
  FrameClockDef def_;
  TimeSource now_;
  double last_ = 0.0;
  std::size_t frames_ = 0;
  std::array<double, kWindow> steps_{};  // ring of raw steps [s]
  std::size_t stepCount_ = 0;
};

}  // namespace hemiroll::platform
