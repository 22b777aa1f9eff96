#include "engine/platform/FramePacer.h"

#include <chrono>
#include <cmath>
#include <thread>

namespace hemiroll::platform {

FramePacer::FramePacer(FramePacerDef def) : def_(std::move(def)) {
  if (!def_.now)
    def_.now = [] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    };
  if (!def_.sleep)
    def_.sleep = [](double seconds) { std::this_thread::sleep_for(std::chrono::duration<double>(seconds)); };
}

void FramePacer::pace(double fps) {
  lastSleep_ = 0.0;
  const double now = def_.now();
  if (!(fps > 0.0) || !std::isfinite(fps) || deadline_ < 0.0) {
    deadline_ = now;
    return;
  }
  const double target = deadline_ + 1.0 / fps;
  if (target <= now) {
    deadline_ = now;  // late: the next interval runs from here, no burst to catch up
    return;
  }
  lastSleep_ = target - now;
  totalSleep_ += lastSleep_;
  def_.sleep(lastSleep_);
  deadline_ = target;
}

}  // namespace hemiroll::platform
