// The peer study's picture of our state as rigid bodies (tools/peers/PeerScene):
// every engine starts from it and is measured by it, so it is checked against
// the model's own kinematics and energy, which it does not call.

#include "tools/peers/PeerScene.h"

#include <gtest/gtest.h>

#include <random>

#include "engine/physics/Energy.h"
#include "engine/physics/RollingDynamics.h"
#include "engine/physics/StateKinematics.h"

namespace hemiroll::tools::peers {
namespace {

physics::ForceDrivenState randomState(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  physics::ForceDrivenState x;
  x << 0.03 * u(rng), 0.03 * u(rng), 0.2 * u(rng), 0.2 * u(rng), 5 * u(rng), 5 * u(rng), 5 * u(rng), 0.1 * u(rng),
      0.1 * u(rng), 1.2 * u(rng), 1.2 * u(rng), 3 * u(rng);
  return x;
}

TEST(PeerSceneTest, PoseRollsTouchesAndPutsThePointWhereTheModelDoes) {
  std::mt19937 rng(7);
  const physics::HemisphereParams params;
  const PeerScene scene;
  for (int i = 0; i < 200; ++i) {
    const physics::ForceDrivenState x = randomState(rng);
    const Pose pose = poseOf(params, x);
    EXPECT_LT((pose.point - physics::massPointPosition(x, params.radius)).norm(), 1e-15);
    const Sample s = sampleOf(scene, pose, 0.0);
    // Rolling: the shell's material point at the contact is at rest; the
    // sphere touches the plane; the point reads back in face coordinates.
    EXPECT_LT(s.slip, 1e-14);
    EXPECT_EQ(s.penetration, 0.0);
    EXPECT_LT((s.p - x.head<2>()).norm(), 1e-15);
    EXPECT_NEAR(std::cos(s.tilt), std::cos(x[physics::force_slot::u_o]) * std::cos(x[physics::force_slot::v_o]), 1e-14);
  }
}

// The energy from two bodies (shell about its centre of mass with 83/320 and
// 2/5 m_s R^2, the point) equals the model's, which uses the inertia about the
// face centre: an error in the inertias, the 3R/8 or a velocity shows here.
TEST(PeerSceneTest, BodiesCarryTheModelsEnergy) {
  std::mt19937 rng(11);
  for (const double shellMass : {0.1, 1.0}) {
    PeerScene scene;
    scene.params.shellMass = shellMass;
    const physics::RollingDynamics dynamics(scene.params);
    for (int i = 0; i < 200; ++i) {
      const physics::ForceDrivenState x = randomState(rng);
      const double model = physics::mechanicalEnergy(dynamics, x).total();
      const double bodies = sampleOf(scene, poseOf(scene.params, x), 0.0).energy;
      EXPECT_NEAR(bodies, model, 1e-13 * (1.0 + std::abs(model)));
    }
  }
}

TEST(PeerSceneTest, TheTetherAddsItsSpring) {
  PeerScene scene;
  scene.drive = PointDrive::Tether;
  scene.tetherStiffness = 250.0;
  const physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  const Pose pose = poseOf(scene.params, x);
  scene.proxy = pose.point + Vec3(0.003, 0.0, 0.004);  // 5 mm away
  const double free = sampleOf(PeerScene{}, pose, 0.0).energy;
  EXPECT_NEAR(sampleOf(scene, pose, 0.0).energy - free, 0.5 * 250.0 * 0.005 * 0.005, 1e-15);
}

TEST(PeerSceneTest, ScenesStartOnTheFaceAtRestOrMovingAsTheirDriveSays) {
  for (const PeerScene& s : peerScenes(false)) {
    SCOPED_TRACE(s.name);
    EXPECT_GT(s.horizon, 0.0);
    EXPECT_LT(s.x0.head<2>().norm(), s.params.radius);
    if (s.drive == PointDrive::Prescribed) {
      const auto want = s.trajectory->at(0.0);
      EXPECT_EQ(s.x0[0], want.p.x());
      EXPECT_EQ(s.x0[1], want.p.y());
      EXPECT_EQ(s.x0[2], want.pDot.x());
      EXPECT_EQ(s.x0[3], want.pDot.y());
    }
    // Horizons are whole numbers of samples, so every engine lands on them.
    EXPECT_NEAR(s.horizon / kSampleInterval, std::round(s.horizon / kSampleInterval), 1e-9);
  }
  for (const PeerScene& s : peerScenes(true)) EXPECT_LE(s.horizon, 0.2);
}

}  // namespace
}  // namespace hemiroll::tools::peers
