#pragma once
// A thread that calls `work` every `interval` until stop(), then once more
// (so whatever arrived before stop() is handled). The recorders use it to
// drain the servo loop's rings; it never touches the servo thread.

#include <atomic>
#include <functional>
#include <thread>

namespace hemiroll::record {

class WriterThread {
 public:
  WriterThread() = default;
  ~WriterThread() { stop(); }
  WriterThread(const WriterThread&) = delete;
  WriterThread& operator=(const WriterThread&) = delete;

  void start(std::function<void()> work, double interval);  // [s]
  void stop();
  bool running() const { return thread_.joinable(); }

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace hemiroll::record
