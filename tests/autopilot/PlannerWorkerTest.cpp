// engine/autopilot/PlannerWorker: one job at a time, refused while busy,
// taken without waiting.

#include "engine/autopilot/PlannerWorker.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "engine/autopilot/Autopilot.h"

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

}  // namespace
}  // namespace hemiroll::autopilot
