#include "engine/autopilot/PlannerWorker.h"

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace hemiroll::autopilot {

PlannerWorker::PlannerWorker(Plan plan, int nice) : plan_(std::move(plan)), nice_(nice), thread_([this] { run(); }) {}

PlannerWorker::~PlannerWorker() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

bool PlannerWorker::post(Autopilot::PlanJob job) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (busy_ || done_) return false;
    job_ = std::move(job);
    busy_ = true;
  }
  wake_.notify_one();
  return true;
}

bool PlannerWorker::take(Autopilot::Decision& out) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!done_) return false;
  out = *done_;
  done_.reset();
  return true;
}

void PlannerWorker::run() {
  // Linux applies nice values per thread; elsewhere (or if refused) it
  // plans at the default priority (AutopilotDef::plannerNice says why not 19).
#if defined(__linux__)
  if (nice_ != 0) setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), nice_);
#endif
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stop_ || job_.has_value(); });
    if (stop_) return;
    const Autopilot::PlanJob job = std::move(*job_);
    job_.reset();
    lock.unlock();
    const Autopilot::Decision decision = plan_(job);
    lock.lock();
    done_ = decision;
    busy_ = false;
  }
}

}  // namespace hemiroll::autopilot
