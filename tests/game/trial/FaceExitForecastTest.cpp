// game/trial/FaceExitForecast: the warning before the mass point leaves the
// face. On made-up states (the arithmetic), and on real trials through the
// servo loop: it fires before a real fall (the human model on a force
// device throws the mass point off the paper's face within seconds,
// docs/HUMAN_MODEL.md) and never during a calm helix (the autopilot winning
// the paper's task).

#include "game/trial/FaceExitForecast.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "engine/physics/Orientation.h"
#include "engine/physics/StateKinematics.h"
#include "engine/script/LevelLoader.h"
#include "game/trial/AutopilotBot.h"
#include "game/trial/BotTrial.h"
#include "game/trial/HumanBot.h"

namespace hemiroll::game {
namespace {

using namespace physics::force_slot;

physics::ForceDrivenState pointAt(double x, double y, double vx, double vy) {
  physics::ForceDrivenState s = physics::ForceDrivenState::Zero();
  s[x_p] = x;
  s[y_p] = y;
  s[xd_p] = vx;
  s[yd_p] = vy;
  return s;
}

TEST(FaceExitForecast, TimesTheRunToTheEdgeAtThePresentVelocity) {
  // R = 0.04: from 1.5 cm off centre at 0.1 m/s outwards, 2.5 cm to go: 0.25 s.
  const FaceExitForecast f = forecastFaceExit(pointAt(0.015, 0.0, 0.1, 0.0), 0.04);
  EXPECT_NEAR(f.timeToEdge, 0.25, 1e-12);
  EXPECT_TRUE(f.warn);
  // Sideways from 3 cm: the chord to the edge is sqrt(4^2 - 3^2) = 2.65 cm.
  EXPECT_NEAR(forecastFaceExit(pointAt(0.03, 0.0, 0.0, 0.05), 0.04).timeToEdge, std::sqrt(7e-4) / 0.05, 1e-12);
  // Slower: beyond the horizon, no warning.
  EXPECT_FALSE(forecastFaceExit(pointAt(0.01, 0.0, 0.05, 0.0), 0.04).warn);
  // Moving inwards from 3 cm at 0.1 m/s: across the face, 7 cm, 0.7 s.
  EXPECT_NEAR(forecastFaceExit(pointAt(0.03, 0.0, -0.1, 0.0), 0.04).timeToEdge, 0.7, 1e-12);
}

// From rest at the centre of a steep face: no velocity to speak of, but at
// 5 m/s^2 along the face (a face tilted 30 degrees, nothing holding the
// point) it slides the 4 cm out in sqrt(2 x 0.04 / 5) = 0.126 s.
TEST(FaceExitForecast, AnAccelerationAlongTheFaceWarnsBeforeAnyVelocityDoes) {
  const physics::ForceDrivenState rest = pointAt(0.0, 0.0, 0.0, 0.0);
  EXPECT_FALSE(forecastFaceExit(rest, 0.04).warn);
  const FaceExitForecast f = forecastFaceExit(rest, 0.04, physics::Vec2(0.0, -5.0));
  EXPECT_TRUE(f.warn);
  EXPECT_NEAR(f.timeToEdgeAccelerating, std::sqrt(2 * 0.04 / 5.0), 1e-9);
  // A calm stir's pull (0.75 m/s^2) from 3 mm off centre: 0.15 s of it
  // moves the point 8 mm, nowhere near the edge.
  EXPECT_FALSE(forecastFaceExit(pointAt(0.003, 0.0, 0.01, 0.0), 0.04, physics::Vec2(0.75, 0.0)).warn);
  // 2 m/s^2 from rest: 0.2 s to the edge, beyond the 0.15 s the
  // acceleration is trusted: not yet.
  const FaceExitForecast later = forecastFaceExit(rest, 0.04, physics::Vec2(2.0, 0.0));
  EXPECT_FALSE(later.warn);
  EXPECT_TRUE(std::isinf(later.timeToEdgeAccelerating));
}

// Upright, gravity is across the face: nothing along it. Tilted by u_o,
// g sin(u_o) along it, and a force that holds the point against it cancels it.
TEST(FaceExitForecast, TheFacesAccelerationIsGravityAndTheForceAlongIt) {
  const physics::HemisphereParams params;  // m_p 1 kg, g 9.81
  physics::ForceDrivenState x = pointAt(0.0, 0.0, 0.0, 0.0);
  EXPECT_NEAR(faceAcceleration(x, params, physics::Vec3::Zero()).norm(), 0.0, 1e-12);
  x[u_o] = 0.2;
  const physics::Vec2 a = faceAcceleration(x, params, physics::Vec3::Zero());
  EXPECT_NEAR(a.norm(), 9.81 * std::sin(0.2), 1e-9);
  // The in-face part of the weight, pushed back by an equal force.
  const physics::Mat3 R = physics::makeOrientation(x[u_o], x[v_o], x[psi]).R;
  const physics::Vec3 weight(0.0, 0.0, -9.81);
  const physics::Vec3 along = weight - weight.dot(R.col(2)) * R.col(2);
  EXPECT_NEAR(faceAcceleration(x, params, -along).norm(), 0.0, 1e-9);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(faceAcceleration(x, params, physics::Vec3(nan, 0, 0)), physics::Vec2::Zero());
}

TEST(FaceExitForecast, AtOrPastTheEdgeWarnsAndNothingWarnsFromNothing) {
  EXPECT_EQ(forecastFaceExit(pointAt(0.04, 0.0, 0.0, 0.0), 0.04).timeToEdge, 0.0);
  EXPECT_TRUE(forecastFaceExit(pointAt(0.0, 0.05, 0.0, 0.0), 0.04).warn);
  const FaceExitForecast still = forecastFaceExit(pointAt(0.039, 0.0, 0.0, 0.0), 0.04);
  EXPECT_FALSE(still.warn);
  EXPECT_TRUE(std::isinf(still.timeToEdge));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(forecastFaceExit(pointAt(nan, 0.0, 1.0, 0.0), 0.04).warn);
  EXPECT_FALSE(forecastFaceExit(pointAt(0.0, 0.0, 1.0, 0.0), nan).warn);
  EXPECT_FALSE(forecastFaceExit(pointAt(0.0, 0.0, 1.0, 0.0), 0.0).warn);
}

// Wraps a bot: every tick, the forecast on the state the bot is shown and
// the force on the mass point (as the window has them from its snapshot).
class Watched final : public script::BotPolicy {
 public:
  explicit Watched(script::BotPolicy& inner) : inner_(inner) {}
  const std::string& name() const override { return inner_.name(); }
  void setTiming(const script::TrialTiming& timing) override { inner_.setTiming(timing); }
  void endTrial() override { inner_.endTrial(); }
  std::string giveUpReason() const override { return inner_.giveUpReason(); }
  void init(const script::BotLevelInfo& info, std::int64_t seed) override {
    radius_ = info.params.radius;
    params_ = info.params;
    inner_.init(info, seed);
  }
  script::BotAction act(const script::BotObservation& obs) override {
    physics::ForceDrivenState x;
    for (int i = 0; i < 12; ++i) x[i] = obs.state[static_cast<std::size_t>(i)];
    const physics::Vec2 a = faceAcceleration(x, params_, physics::vec3Of(obs.force));
    warning = forecastFaceExit(x, radius_, a).warn;
    if (warning) {
      ++warnings;
      // The first warning of the last second (the window holds a warning on
      // screen for 0.6 s, so flickers within it read as one).
      if (obs.time - lastWarning > 1.0) firstOfLatest = obs.time;
      lastWarning = obs.time;
    }
    return inner_.act(obs);
  }

  long warnings = 0;
  bool warning = false;
  double firstOfLatest = -1.0, lastWarning = -1e9;

 private:
  script::BotPolicy& inner_;
  double radius_ = 0.04;
  physics::HemisphereParams params_;
};

TrialResult playWatched(const char* file, Watched& watched, std::uint64_t seed) {
  script::LevelLoadOptions options;
  options.seed = seed;
  script::LoadedLevel level =
      script::LevelLoader(options).loadFile(std::string(HEMIROLL_SOURCE_DIR) + "/levels/" + file);
  TrialSettings settings;
  settings.seed = seed;
  return BotTrial(level, watched, settings).run();
}

// A real fall: the warning is on at the end and came on at least 0.1 s
// before it (a third of the horizon: the point accelerates outwards, so it
// arrives sooner than its present velocity says), and not long before (a
// warning that stays on for seconds tells nothing). Warnings less than a
// second apart count as one stretch.
TEST(FaceExitForecast, WarnsBeforeARealFall) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    HumanBotOptions options;
    options.human.device = human::HandDevice::Haptic;
    options.human.coContracts = false;  // the relaxed arm lets the mass point off the face within seconds
    HumanBot person(options);
    Watched watched(person);
    const TrialResult r = playWatched("paper_reaching.lua", watched, seed);
    ASSERT_EQ(r.reason, script::trial_reason::kLeftFace) << "seed " << seed << ": the fall this test needs did not happen";
    EXPECT_TRUE(watched.warning) << "seed " << seed;
    const double lead = r.time - watched.firstOfLatest;
    EXPECT_GE(lead, 0.1) << "seed " << seed << ": warned at " << watched.firstOfLatest << " s, fell at " << r.time;
    EXPECT_LE(lead, 2.0) << "seed " << seed << ": warned at " << watched.firstOfLatest << " s, fell at " << r.time;
  }
}

TEST(FaceExitForecast, StaysQuietThroughACalmHelix) {
  AutopilotBot autopilot;
  Watched watched(autopilot);
  const TrialResult r = playWatched("paper_reaching.lua", watched, 0);
  ASSERT_EQ(r.outcome, script::TrialOutcome::Success) << r.reason;
  EXPECT_EQ(watched.warnings, 0) << "over " << r.time << " s of helix";
}

}  // namespace
}  // namespace hemiroll::game
