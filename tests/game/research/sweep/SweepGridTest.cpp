// game/research/sweep/SweepGrid: point i of a sweep - the last axis fastest, the
// axis values applied to the base, the start tilt computed per point - and
// the scenario it runs.

#include "game/research/sweep/SweepGrid.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "engine/physics/StateLayout.h"
#include "engine/script/SweepLoader.h"
#include "game/research/sweep/StaticTilt.h"

namespace hemiroll::game {
namespace {

using ::testing::ElementsAre;

task::SweepDef spec(const std::string& source) { return script::SweepLoader().loadSource(source, "s.lua"); }

TEST(SweepGrid, TheLastAxisVariesFastest) {
  const SweepGrid grid(spec(R"(return { axes = {
      { param = "k", values = { 6, 8 } },
      { param = "m_p", values = { 0.5, 1, 2 } },
      { param = "r2", values = { 0.004, 0.006 } } } })"));
  ASSERT_EQ(grid.size(), 12);
  EXPECT_THAT(grid.point(0).position, ElementsAre(0, 0, 0));
  EXPECT_THAT(grid.point(1).position, ElementsAre(0, 0, 1));
  EXPECT_THAT(grid.point(2).position, ElementsAre(0, 1, 0));
  EXPECT_THAT(grid.point(7).position, ElementsAre(1, 0, 1));
  EXPECT_THAT(grid.point(11).position, ElementsAre(1, 2, 1));
  const SweepPoint p = grid.point(7);
  EXPECT_EQ(p.index, 7);
  EXPECT_EQ(p.rose.k, 8.0);
  EXPECT_EQ(p.params.pointMass, 0.5);
  EXPECT_EQ(p.rose.r2, 0.006);
  EXPECT_EQ(p.rose.r1, 0.015);  // the base where no axis says otherwise
  EXPECT_EQ(p.params.shellMass, 0.1);
  EXPECT_THROW(grid.point(12), std::out_of_range);
  EXPECT_THROW(grid.point(-1), std::out_of_range);
}

TEST(SweepGrid, TheStartTiltFollowsEachPointsMassesAndLinks) {
  const SweepGrid grid(spec(R"(return { axes = {
      { param = "m_p", values = { 0.5, 2 } }, { param = "r1", values = { 0.01, 0.02 } } } })"));
  for (long long i = 0; i < grid.size(); ++i) {
    const SweepPoint p = grid.point(i);
    EXPECT_EQ(p.startTilt, staticTilt(p.params, p.rose.r1 + p.rose.r2));
    EXPECT_GT(p.startTilt, 0.0);
    const task::ScenarioDef s = grid.scenario(p);
    EXPECT_EQ(s.drive.kind, task::DriveKind::Rose);
    EXPECT_EQ(s.initial[physics::force_slot::u_o], -p.startTilt);  // lowers the mass point (StaticTilt.h)
    EXPECT_EQ(s.params.pointMass, p.params.pointMass);
    EXPECT_EQ(s.drive.rose.r1, p.rose.r1);
  }
  EXPECT_NE(grid.point(0).startTilt, grid.point(3).startTilt);
}

TEST(SweepGrid, FromRestStartsUpright) {
  const SweepGrid grid(spec("return { start = 'rest', duration = 5, dt = 0.002, axes = { { param = 'k', values = { 6 } } } }"));
  const SweepPoint p = grid.point(0);
  EXPECT_EQ(p.startTilt, 0.0);
  const task::ScenarioDef s = grid.scenario(p);
  EXPECT_TRUE(s.initial.isZero());
  EXPECT_EQ(s.duration, 5.0);
  EXPECT_EQ(s.timeStep, 0.002);
}

}  // namespace
}  // namespace hemiroll::game
