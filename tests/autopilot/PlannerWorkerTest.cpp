// engine/autopilot/PlannerWorker: one job at a time, refused while busy,
// taken without waiting.

#include "engine/autopilot/PlannerWorker.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "engine/autopilot/Autopilot.h"

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace hemiroll::autopilot {
namespace {

TEST(PlannerWorker, RunsOneJobAtATimeAndHandsBackItsDecision) {
  std::atomic<bool> release{false};
  PlannerWorker worker([&](const Autopilot::PlanJob& job) {
    while (!release.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    Autopilot::Decision d;
    d.generation = job.generation;
    d.steer = true;
    d.steerAngle = job.input.time;
    return d;
  });
  const physics::ModelConstants constants{physics::HemisphereParams{}};
  HelixPolicy policy(constants, HelixParams{}, 0.001);
  Autopilot::PlanJob job(policy);
  job.generation = 7;
  job.input.time = 1.25;
  ASSERT_TRUE(worker.post(job));
  EXPECT_FALSE(worker.post(job));  // busy: refused, not queued
  Autopilot::Decision d;
  EXPECT_FALSE(worker.take(d));    // not done yet: take does not wait
  release = true;
  for (int i = 0; i < 5000 && !worker.take(d); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_EQ(d.generation, 7u);
  EXPECT_EQ(d.steerAngle, 1.25);
  EXPECT_TRUE(worker.post(job));   // free again once taken
}

#if defined(__linux__)
// The planning thread's nice value, as its job sees it: the one it is given
// (AutopilotDef::plannerNice; 19 starved it behind any other program).
int niceOfAWorkersJob(int nice) {
  PlannerWorker worker(
      [](const Autopilot::PlanJob&) {
        Autopilot::Decision d;
        d.steerAngle = getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
        return d;
      },
      nice);
  const physics::ModelConstants constants{physics::HemisphereParams{}};
  HelixPolicy policy(constants, HelixParams{}, 0.001);
  EXPECT_TRUE(worker.post(Autopilot::PlanJob(policy)));
  Autopilot::Decision d;
  d.steerAngle = -100.0;
  for (int i = 0; i < 5000 && !worker.take(d); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return static_cast<int>(d.steerAngle);
}

TEST(PlannerWorker, PlansAtTheNiceValueItIsGiven) {
  const int ours = getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
  EXPECT_EQ(niceOfAWorkersJob(0), ours);  // 0: left as the process runs
  if (ours < 7) {
    EXPECT_EQ(niceOfAWorkersJob(7), 7);
  }
}
#endif

}  // namespace
}  // namespace hemiroll::autopilot
