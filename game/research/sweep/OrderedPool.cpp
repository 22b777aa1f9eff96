#include "game/research/sweep/OrderedPool.h"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace hemiroll::game {

int OrderedPool::defaultThreads() {
  // The CPUs this process may run on: a cluster's job (Slurm's cgroup, taskset)
  // gets fewer than the machine has, and more threads than those only queue.
  cpu_set_t allowed;
  if (sched_getaffinity(0, sizeof allowed, &allowed) == 0) return std::max(1, CPU_COUNT(&allowed));
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void OrderedPool::run(std::size_t jobs, const Work& work, const Deliver& deliver, const Tick& tick,
                      double tickInterval) const {
  // One thread and no progress to report: the jobs run here, one after the
  // other, each delivered when done - the order the pool delivers them in -
  // without a thread to start, wake and join (~0.1 ms of a short sweep). A
  // tick keeps the pool: a long job would hold back every tick until it ends.
  if (threads_ == 1 && !tick) {
    for (std::size_t job = 0; job < jobs; ++job) deliver(job, work(job));
    return;
  }
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::optional<std::string>> done(jobs);
  std::exception_ptr failure;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};

  auto worker = [&] {
    for (std::size_t job; !stop.load() && (job = next.fetch_add(1)) < jobs;) {
      try {
        std::string result = work(job);
        const std::lock_guard lock(mutex);
        done[job] = std::move(result);
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!failure) failure = std::current_exception();
        stop = true;
      }
      changed.notify_one();
    }
  };

  const int count = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads_), std::max<std::size_t>(jobs, 1)));
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) pool.emplace_back(worker);
  // Joins on every way out, an exception from deliver or tick included.
  struct Joiner {
    std::vector<std::thread>& pool;
    std::atomic<bool>& stop;
    ~Joiner() {
      stop = true;
      for (std::thread& t : pool)
        if (t.joinable()) t.join();
    }
  } joiner{pool, stop};

  const auto interval = std::chrono::duration<double>(tickInterval);
  std::size_t delivered = 0;
  auto lastTick = std::chrono::steady_clock::now();
  while (delivered < jobs) {
    std::optional<std::string> result;
    {
      std::unique_lock lock(mutex);
      changed.wait_for(lock, interval, [&] { return failure || done[delivered].has_value(); });
      if (failure) break;
      if (done[delivered]) result = std::exchange(done[delivered], std::nullopt);
    }
    if (result) deliver(delivered++, std::move(*result));
    if (tick && std::chrono::steady_clock::now() - lastTick >= interval) {
      lastTick = std::chrono::steady_clock::now();
      tick(delivered);
    }
  }
  stop = true;
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  if (tick) tick(delivered);
}

}  // namespace hemiroll::game
