#include "game/ui/view/RenderSceneBuilder.h"

#include <gtest/gtest.h>

#include "engine/physics/Orientation.h"

namespace hemiroll::game {
namespace {

namespace slot = physics::force_slot;
using task::TaskVariable;

task::LevelDef paperLikeLevel() {
  task::LevelDef level;
  level.params.radius = 0.05;
  task::StageDef stage;
  stage.targets = {{TaskVariable::x_p, 0.0, 0.004}, {TaskVariable::u_a, -0.04, 0.004}, {TaskVariable::v_a, -0.03, 0.002}};
  level.task.stages.push_back(stage);
  task::ZoneDef zone;
  zone.shape = task::ZoneShape::Box;
  zone.min = {0.1, 0.1};
  zone.max = {0.2, 0.15};
  level.task.forbidden.push_back(zone);
  return level;
}

TEST(RenderSceneBuilderTest, PoseFromTheState) {
  const task::LevelDef level = paperLikeLevel();
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  x[slot::u_a] = 0.01;
  x[slot::v_a] = -0.02;
  x[slot::u_o] = 0.3;
  x[slot::v_o] = -0.2;
  x[slot::psi] = 1.1;
  x[slot::x_p] = 0.01;
  render::RenderScene scene;
  fillFromState(level, x, 0, scene);
  EXPECT_EQ(scene.radius, 0.05);
  EXPECT_EQ(scene.centre, (render::Vec3d{0.01, -0.02, 0.05}));
  const physics::Orientation o = physics::makeOrientation(0.3, -0.2, 1.1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(scene.orientation[3 * i + j], o.R(i, j));  // copied, not recomputed
  EXPECT_EQ(scene.massPoint, (render::Vec2d{0.01, 0.0}));
}

TEST(RenderSceneBuilderTest, TheContactTargetAndZonesOfTheStage) {
  const task::LevelDef level = paperLikeLevel();
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  render::RenderScene scene;
  fillFromState(level, x, 0, scene);
  ASSERT_EQ(scene.targets.size(), 1u);  // x_p is not on the plane: only u_a, v_a make the marker
  EXPECT_EQ(scene.targets[0].position, (render::Vec2d{-0.04, -0.03}));
  EXPECT_EQ(scene.targets[0].halfWidth, (render::Vec2d{0.004, 0.002}));
  EXPECT_FALSE(scene.targets[0].inside);
  ASSERT_EQ(scene.forbidden.size(), 1u);
  EXPECT_FALSE(scene.forbidden[0].circle);
  EXPECT_EQ(scene.forbidden[0].max, (render::Vec2d{0.2, 0.15}));

  x[slot::u_a] = -0.037;  // 3 mm off in u (tolerance 4 mm), 1 mm in v (2 mm)
  x[slot::v_a] = -0.031;
  fillFromState(level, x, 0, scene);
  ASSERT_EQ(scene.targets.size(), 1u);  // refilled, not appended
  EXPECT_TRUE(scene.targets[0].inside);

  fillFromState(level, x, 5, scene);  // past the last stage: nothing to reach
  EXPECT_TRUE(scene.targets.empty());
}

TEST(RenderSceneBuilderTest, AFreeComponentGetsAWideBand) {
  task::LevelDef level;
  task::StageDef stage;
  stage.targets = {{TaskVariable::u_a, 0.05, 0.01}};
  level.task.stages.push_back(stage);
  render::RenderScene scene;
  fillFromState(level, physics::ForceDrivenState::Zero(), 0, scene);
  ASSERT_EQ(scene.targets.size(), 1u);
  EXPECT_GT(scene.targets[0].halfWidth[1], 1.0);  // wider than any floor: v_a is free
}

TEST(RenderSceneBuilderTest, SnapshotAddsProxySpringAndForce) {
  const task::LevelDef level = paperLikeLevel();
  haptics::ServoSnapshot snap;
  snap.proxyPosition = {0.01, 0.02, 0.06};
  snap.handForce = {0.5, -1.0, 2.0};
  snap.time = 3.5;
  snap.engagement = haptics::Engagement::Engaged;
  render::RenderScene scene;
  fillFromSnapshot(level, snap, 0, scene);
  EXPECT_TRUE(scene.showProxy);
  EXPECT_TRUE(scene.springOn);
  EXPECT_EQ(scene.proxyPosition, snap.proxyPosition);
  EXPECT_EQ(scene.force, snap.handForce);
  EXPECT_EQ(scene.time, 3.5);
  snap.engagement = haptics::Engagement::Disengaged;
  fillFromSnapshot(level, snap, 0, scene);
  EXPECT_FALSE(scene.springOn);
}

}  // namespace
}  // namespace hemiroll::game
