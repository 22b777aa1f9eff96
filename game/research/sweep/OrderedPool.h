#pragma once
// Runs independent jobs 0..n-1 on a pool of std::threads and hands their
// results to the calling thread in job order, as soon as each prefix is
// done: the output is the same for any thread count, because each job's
// result depends on its index alone and the reduction (the caller's
// `deliver`) sees them in a fixed order.
//
// The calling thread only delivers and reports progress; `work` runs on the
// pool's threads and must not touch shared state. (With one thread and no
// tick, everything runs on the calling thread, in the same order.) An exception from `work`
// stops the pool (jobs not yet started are skipped) and is rethrown from
// run() after every thread has joined; so is one from `deliver` or `tick`.

#include <cstddef>
#include <functional>
#include <string>

namespace hemiroll::game {

class OrderedPool {
 public:
  using Work = std::function<std::string(std::size_t job)>;
  using Deliver = std::function<void(std::size_t job, std::string&& result)>;
  // Called on the calling thread about every `tickInterval` seconds and once
  // at the end, with the number of jobs delivered so far.
  using Tick = std::function<void(std::size_t delivered)>;

  explicit OrderedPool(int threads) : threads_(threads < 1 ? 1 : threads) {}

  void run(std::size_t jobs, const Work& work, const Deliver& deliver, const Tick& tick = {},
           double tickInterval = 0.2) const;

  // The CPUs this process may run on (its affinity mask, which Slurm and
  // taskset set), else std::thread::hardware_concurrency(); at least 1.
  static int defaultThreads();

 private:
  int threads_;
};

}  // namespace hemiroll::game
