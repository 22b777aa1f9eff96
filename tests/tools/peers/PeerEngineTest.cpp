// The driver every peer runs under (tools/peers/PeerEngine: runPeer), with a
// stand-in engine whose bodies move as the test says: the drive it is given,
// the samples it takes, and where it stops a run.

#include "tools/peers/PeerEngine.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hemiroll::tools::peers {
namespace {

// What the stand-in world was told; kept by the engine, since runPeer
// destroys the world when the run ends.
struct Told {
  Vec3 force = Vec3::Zero();  // the last force
  int forcesSet = 0, steps = 0;
};

// Bodies at the scene's start; the point slides along the face's x by `drift`
// per step (to leave the face on purpose).
class StandInWorld final : public PeerWorld {
 public:
  StandInWorld(const PeerScene& scene, double drift, Told& told)
      : pose_(poseOf(scene.params, scene.x0)), drift_(drift), told_(told) {}
  Pose pose() const override { return pose_; }
  void setPointForce(const Vec3& f) override {
    told_.force = f;
    ++told_.forcesSet;
  }
  void step() override {
    pose_.point += drift_ * pose_.rotation.col(0);
    ++told_.steps;
  }

 private:
  Pose pose_;
  double drift_;
  Told& told_;
};

class StandInEngine final : public PeerEngine {
 public:
  explicit StandInEngine(double drift) : drift_(drift) {}
  std::string name() const override { return "stand-in"; }
  std::string version() const override { return "0"; }
  std::vector<PeerSetting> settings() const override { return {{"only", ""}}; }
  std::unique_ptr<PeerWorld> build(const PeerScene& scene, const std::string&, double, std::string&) const override {
    told = Told{};
    return std::make_unique<StandInWorld>(scene, drift_, told);
  }
  mutable Told told;

 private:
  double drift_;
};

PeerScene sceneNamed(const std::string& name) {
  for (const PeerScene& s : peerScenes(true))
    if (s.name == name) return s;
  ADD_FAILURE() << "no scene " << name;
  return {};
}

TEST(PeerEngineTest, ARunSamplesEveryIntervalAndStepsItsWholeHorizon) {
  const PeerScene scene = sceneNamed("free_heavy");
  const StandInEngine engine(0.0);
  const RunResult r = runPeer(engine, scene, "only", 5e-4);
  EXPECT_TRUE(r.failure.empty()) << r.failure;
  ASSERT_EQ(r.samples.size(), static_cast<std::size_t>(std::lround(scene.horizon / kSampleInterval)) + 1);
  EXPECT_DOUBLE_EQ(r.samples.back().t, scene.horizon);
  EXPECT_EQ(engine.told.steps, static_cast<int>(std::lround(scene.horizon / 5e-4)));
  EXPECT_EQ(engine.told.forcesSet, 0);  // free motion: nothing pushes the point
}

TEST(PeerEngineTest, TheTetherPullsThePointTowardsTheProxyEveryStep) {
  const PeerScene scene = sceneNamed("tether");
  const StandInEngine engine(0.0);
  runPeer(engine, scene, "only", 1e-3);
  const Pose start = poseOf(scene.params, scene.x0);
  EXPECT_EQ(engine.told.forcesSet, engine.told.steps);
  EXPECT_LT((engine.told.force - scene.tetherStiffness * (scene.proxy - start.point)).norm(), 1e-12);
}

TEST(PeerEngineTest, TheHandPushesOnlyInTheFacePlane) {
  const PeerScene scene = sceneNamed("rose");
  const StandInEngine engine(0.0);
  runPeer(engine, scene, "only", 1e-3);
  const Pose start = poseOf(scene.params, scene.x0);
  EXPECT_EQ(engine.told.forcesSet, engine.told.steps);
  EXPECT_NEAR(engine.told.force.dot(start.rotation.col(2)), 0.0, 1e-12);  // the face carries the normal part
  EXPECT_GT(engine.told.force.norm(), 0.0);  // the stand-in point stands still off its moving path
}

TEST(PeerEngineTest, ARunThatLeavesTheModelStopsThereAndSaysWhy) {
  const PeerScene scene = sceneNamed("free_heavy");
  // 1 mm a step from the centre: past the 40 mm rim at the 40th step.
  const StandInEngine engine(1e-3);
  const RunResult r = runPeer(engine, scene, "only", 1e-3);
  EXPECT_TRUE(r.samples.empty());
  EXPECT_EQ(r.failure, "the point left the face at t = 0.0400 s");
  EXPECT_EQ(engine.told.steps, 40);
}

}  // namespace
}  // namespace hemiroll::tools::peers
