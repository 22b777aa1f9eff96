// game/research/sweep/OrderedPool: results delivered in job order whatever the thread
// count and whichever job finishes first; an exception from a job or from
// delivery stops the pool and reaches the caller after the threads joined.

#include "game/research/sweep/OrderedPool.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace hemiroll::game {
namespace {

// Later jobs finish first: job j sleeps (n - j) * 0.2 ms.
std::string slowFirst(std::size_t job, std::size_t n) {
  std::this_thread::sleep_for(std::chrono::microseconds(200 * (n - job)));
  return "job " + std::to_string(job);
}

TEST(OrderedPool, DeliversInJobOrderForAnyThreadCount) {
  constexpr std::size_t kJobs = 40;
  for (const int threads : {1, 2, 3, 8}) {
    std::vector<std::size_t> order;
    std::vector<std::string> results;
    std::size_t lastTick = 0;
    int ticks = 0;
    OrderedPool(threads).run(
        kJobs, [](std::size_t job) { return slowFirst(job, kJobs); },
        [&](std::size_t job, std::string&& r) {
          order.push_back(job);
          results.push_back(std::move(r));
        },
        [&](std::size_t delivered) {
          EXPECT_GE(delivered, lastTick);
          lastTick = delivered;
          ++ticks;
        },
        0.001);
    ASSERT_EQ(order.size(), kJobs) << threads;
    for (std::size_t j = 0; j < kJobs; ++j) {
      EXPECT_EQ(order[j], j);
      EXPECT_EQ(results[j], "job " + std::to_string(j));
    }
    EXPECT_EQ(lastTick, kJobs);  // the last tick reports everything
    EXPECT_GE(ticks, 1);
  }
}

TEST(OrderedPool, NoJobsIsNothingToDo) {
  int delivered = 0;
  OrderedPool(4).run(0, [](std::size_t) { return std::string(); }, [&](std::size_t, std::string&&) { ++delivered; });
  EXPECT_EQ(delivered, 0);
}

TEST(OrderedPool, AFailingJobStopsThePoolAndIsRethrown) {
  std::atomic<int> started{0};
  std::vector<std::size_t> delivered;
  EXPECT_THROW(OrderedPool(2).run(
                   1000,
                   [&](std::size_t job) -> std::string {
                     ++started;
                     if (job == 5) throw std::runtime_error("job 5 failed");
                     // Jobs take a while, as sweep points do: with empty jobs the
                     // other worker could run all 1000 in the moment between job
                     // 5's throw and the pool's stop (seen under ctest -j2).
                     std::this_thread::sleep_for(std::chrono::microseconds(200));
                     return "";
                   },
                   [&](std::size_t job, std::string&&) { delivered.push_back(job); }),
               std::runtime_error);
  EXPECT_LT(started.load(), 1000);  // the rest were skipped
  for (std::size_t j = 0; j < delivered.size(); ++j) EXPECT_EQ(delivered[j], j);
  EXPECT_LE(delivered.size(), 5u);
}

TEST(OrderedPool, AFailingDeliveryStopsThePoolAndIsRethrown) {
  std::atomic<int> started{0};
  EXPECT_THROW(OrderedPool(2).run(
                   1000,
                   [&](std::size_t) {
                     ++started;
                     std::this_thread::sleep_for(std::chrono::microseconds(100));
                     return std::string();
                   },
                   [&](std::size_t job, std::string&&) {
                     if (job == 3) throw std::runtime_error("disk full");
                   }),
               std::runtime_error);
  EXPECT_LT(started.load(), 1000);
}

TEST(OrderedPool, OneThreadWithoutTicksRunsOnTheCallingThreadInOrder) {
  constexpr std::size_t kJobs = 12;
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::string> results;
  std::vector<std::string> events;  // work and delivery interleaved, as they happened
  OrderedPool(1).run(
      kJobs,
      [&](std::size_t job) {
        EXPECT_EQ(std::this_thread::get_id(), caller);
        events.push_back("work " + std::to_string(job));
        return slowFirst(job, kJobs);
      },
      [&](std::size_t job, std::string&& r) {
        events.push_back("deliver " + std::to_string(job));
        results.push_back(std::move(r));
      });
  ASSERT_EQ(results.size(), kJobs);
  for (std::size_t j = 0; j < kJobs; ++j) {
    EXPECT_EQ(results[j], "job " + std::to_string(j));
    EXPECT_EQ(events[2 * j], "work " + std::to_string(j));  // each delivered before the next starts
    EXPECT_EQ(events[2 * j + 1], "deliver " + std::to_string(j));
  }
  // A failing job: the earlier ones delivered, the later ones never started.
  std::vector<std::size_t> delivered;
  std::size_t started = 0;
  EXPECT_THROW(OrderedPool(1).run(
                   10,
                   [&](std::size_t job) -> std::string {
                     ++started;
                     if (job == 5) throw std::runtime_error("job 5 failed");
                     return "";
                   },
                   [&](std::size_t job, std::string&&) { delivered.push_back(job); }),
               std::runtime_error);
  EXPECT_EQ(started, 6u);
  EXPECT_EQ(delivered, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
}

}  // namespace
}  // namespace hemiroll::game
