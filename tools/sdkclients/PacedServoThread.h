#pragma once
// A servo loop for SDKs that have none of their own (Force Dimension's DHD,
// libnifalcon): a thread that calls step() once per period on absolute
// deadlines, so that a late tick does not shift every later one.

#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>

namespace hemiroll::sdkclients {

class PacedServoThread {
 public:
  ~PacedServoThread() { stop(); }
  // step is called from the new thread until stop(); made once, before the loop.
  void start(std::int64_t periodNs, std::function<void(std::int64_t nowNs)> step);
  void stop();

 private:
  std::atomic<bool> running_{false};
  std::thread thread_;
};

}  // namespace hemiroll::sdkclients
