#include "engine/record/WriterThread.h"

#include <chrono>
#include <utility>

namespace hemiroll::record {

void WriterThread::start(std::function<void()> work, double interval) {
  if (thread_.joinable()) return;
  stop_.store(false, std::memory_order_relaxed);
  const auto period = std::chrono::duration<double>(interval);
  thread_ = std::thread([this, work = std::move(work), period] {
    while (!stop_.load(std::memory_order_acquire)) {
      work();
      std::this_thread::sleep_for(period);
    }
    work();  // what arrived before stop()
  });
}

void WriterThread::stop() {
  if (!thread_.joinable()) return;
  stop_.store(true, std::memory_order_release);
  thread_.join();
}

}  // namespace hemiroll::record
