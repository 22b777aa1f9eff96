// game/research/sim/RoseLockstepRun: several rose scenarios in SIMD lanes give, lane
// by lane, the rows and summary ScenarioRun gives each alone, bit for bit:
// lanes that tip over (located by the scalar Stepper) among lanes that do
// not, a sampling interval, and a duration that is not a whole number of
// steps (the last step shortened). Other drives and integrators are refused.

#include "game/research/sim/RoseLockstepRun.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "engine/physics/BatchedRk4.h"
#include "engine/physics/StateLayout.h"
#include "game/research/sweep/SweepGrid.h"
#include "tests/game/support/TinySweep.h"

namespace hemiroll::game {
namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameRow(const TrajectoryRow& a, const TrajectoryRow& b) {
  bool same = sameBits(a.time, b.time) && sameBits(a.energy, b.energy);
  for (int i = 0; i < 12; ++i) same = same && sameBits(a.state[i], b.state[i]);
  for (int i = 0; i < 2; ++i) same = same && sameBits(a.faceForce[i], b.faceForce[i]);
  return same;
}

// kTippingSweep's four points from rest (two tip over within 3 s) and
// kTinySweep's nine from the static tilt: thirteen lanes, not a multiple of
// any width.
std::vector<task::ScenarioDef> scenarios() {
  std::vector<task::ScenarioDef> out;
  for (const char* source : {test::kTippingSweep, test::kTinySweep}) {
    const SweepGrid grid(test::sweepOf(source));
    for (long long i = 0; i < grid.size(); ++i) out.push_back(grid.scenario(grid.point(i)));
  }
  return out;
}

TEST(RoseLockstepRun, EveryLaneHasTheRowsAndSummaryOfItsScalarRun) {
  RunSettings settings;
  settings.duration = 2.0005;  // 2000 steps of 1 ms and one of 0.5 ms
  settings.timeStep = 1e-3;
  settings.every = 7;
  const std::vector<task::ScenarioDef> all = scenarios();
  std::vector<std::vector<TrajectoryRow>> expected(all.size());
  std::vector<RunSummary> expectedSummaries;
  int tipped = 0;
  for (std::size_t lane = 0; lane < all.size(); ++lane) {
    expectedSummaries.push_back(
        ScenarioRun(all[lane], settings).run([&](const TrajectoryRow& row) { expected[lane].push_back(row); }));
    tipped += expectedSummaries.back().event != physics::DomainEvent::None;
  }
  ASSERT_GE(tipped, 1) << "the test needs a lane that stops among lanes that go on";
  ASSERT_LT(tipped, static_cast<int>(all.size()));

  for (int width : {1, 2, 4, 8}) {
    if (!physics::laneWidthSupported(width)) continue;
    std::vector<std::vector<TrajectoryRow>> got(all.size());
    const std::vector<RunSummary> summaries = RoseLockstepRun(all, settings, width).run(
        [&](std::size_t lane, const TrajectoryRow& row) { got[lane].push_back(row); });
    ASSERT_EQ(summaries.size(), all.size());
    for (std::size_t lane = 0; lane < all.size(); ++lane) {
      const RunSummary& a = summaries[lane];
      const RunSummary& b = expectedSummaries[lane];
      EXPECT_EQ(a.event, b.event) << "width " << width << ", lane " << lane;
      EXPECT_EQ(a.steps, b.steps) << "width " << width << ", lane " << lane;
      EXPECT_TRUE(sameBits(a.endTime, b.endTime) && sameBits(a.finalEnergy, b.finalEnergy))
          << "width " << width << ", lane " << lane << ": ended at " << a.endTime << " vs " << b.endTime;
      ASSERT_EQ(got[lane].size(), expected[lane].size()) << "width " << width << ", lane " << lane;
      for (std::size_t r = 0; r < got[lane].size(); ++r)
        ASSERT_TRUE(sameRow(got[lane][r], expected[lane][r]))
            << "width " << width << ", lane " << lane << ", row " << r << " at t = " << expected[lane][r].time;
    }
  }
}

// A sweep's rows (StateOnly): the same times, states, positions of the mass
// point and events as the full rows, without the mass point's velocity, the
// energy and the face force, which a sweep does not measure.
TEST(RoseLockstepRun, StateOnlyRowsAreTheFullRowsWithoutVelocityEnergyAndForce) {
  RunSettings settings;
  settings.duration = 1.5;
  settings.every = 10;
  const std::vector<task::ScenarioDef> all = scenarios();
  const int width = physics::bestLaneWidth();
  std::vector<std::vector<TrajectoryRow>> full(all.size()), lean(all.size());
  const std::vector<RunSummary> fullSummaries = RoseLockstepRun(all, settings, width).run(
      [&](std::size_t lane, const TrajectoryRow& row) { full[lane].push_back(row); });
  const std::vector<RunSummary> leanSummaries =
      RoseLockstepRun(all, settings, width, RoseLockstepRun::RowContent::StateOnly)
          .run([&](std::size_t lane, const TrajectoryRow& row) { lean[lane].push_back(row); });
  for (std::size_t lane = 0; lane < all.size(); ++lane) {
    EXPECT_EQ(leanSummaries[lane].event, fullSummaries[lane].event) << lane;
    EXPECT_EQ(leanSummaries[lane].steps, fullSummaries[lane].steps) << lane;
    EXPECT_TRUE(sameBits(leanSummaries[lane].endTime, fullSummaries[lane].endTime)) << lane;
    ASSERT_EQ(lean[lane].size(), full[lane].size()) << lane;
    for (std::size_t r = 0; r < lean[lane].size(); ++r) {
      TrajectoryRow expected = full[lane][r];
      expected.state.segment<2>(physics::force_slot::xd_p).setZero();
      expected.energy = 0.0;
      expected.faceForce.setZero();
      ASSERT_TRUE(sameRow(lean[lane][r], expected)) << "lane " << lane << ", row " << r;
    }
  }
}

TEST(RoseLockstepRun, TakesOnlyRoseDrivesWithRk4) {
  const std::vector<task::ScenarioDef> all = scenarios();
  RunSettings settings;
  EXPECT_TRUE(RoseLockstepRun::eligible(all.front(), settings));
  settings.integrator = "dopri5";
  EXPECT_FALSE(RoseLockstepRun::eligible(all.front(), settings));
  EXPECT_THROW(RoseLockstepRun(all, settings, 1), std::invalid_argument);
  task::ScenarioDef free = all.front();
  free.drive.kind = task::DriveKind::Free;
  EXPECT_FALSE(RoseLockstepRun::eligible(free, RunSettings{}));
}

}  // namespace
}  // namespace hemiroll::game
