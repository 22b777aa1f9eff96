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
  // R = 0.04: from 1 cm off centre at 0.1 m/s outwards, 3 cm to go: 0.3 s.
  const FaceExitForecast f = forecastFaceExit(pointAt(0.01, 0.0, 0.1, 0.0), 0.04);
  EXPECT_NEAR(f.timeToEdge, 0.3, 1e-12);
  EXPECT_TRUE(f.warn);
  // Sideways from 3 cm: the chord to the edge is sqrt(4^2 - 3^2) = 2.65 cm.
  EXPECT_NEAR(forecastFaceExit(pointAt(0.03, 0.0, 0.0, 0.05), 0.04).timeToEdge, std::sqrt(7e-4) / 0.05, 1e-12);
  // Slower: beyond the horizon, no warning.
  EXPECT_FALSE(forecastFaceExit(pointAt(0.01, 0.0, 0.05, 0.0), 0.04).warn);
  // Moving inwards from 3 cm at 0.1 m/s: across the face, 7 cm, 0.7 s.
  EXPECT_NEAR(forecastFaceExit(pointAt(0.03, 0.0, -0.1, 0.0), 0.04).timeToEdge, 0.7, 1e-12);
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

// Wraps a bot: every tick, the forecast on the state the bot is shown.
class Watched final : public script::BotPolicy {
 public:
  explicit Watched(script::BotPolicy& inner) : inner_(inner) {}
  const std::string& name() const override { return inner_.name(); }
  void setTiming(const script::TrialTiming& timing) override { inner_.setTiming(timing); }
  void endTrial() override { inner_.endTrial(); }
  std::string giveUpReason() const override { return inner_.giveUpReason(); }
  void init(const script::BotLevelInfo& info, std::int64_t seed) override {
    radius_ = info.params.radius;
    inner_.init(info, seed);
  }
  script::BotAction act(const script::BotObservation& obs) override {
    physics::ForceDrivenState x;
    for (int i = 0; i < 12; ++i) x[i] = obs.state[static_cast<std::size_t>(i)];
    if (forecastFaceExit(x, radius_).warn) {
      ++warnings;
      if (!warning) lastOnset = obs.time;  // the start of the latest stretch of warning
      warning = true;
    } else {
      warning = false;
    }
    return inner_.act(obs);
  }

  long warnings = 0;
  bool warning = false;
  double lastOnset = -1.0;

 private:
  script::BotPolicy& inner_;
  double radius_ = 0.04;
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
// warning that stays on for seconds tells nothing).
TEST(FaceExitForecast, WarnsBeforeARealFall) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    HumanBotOptions options;
    options.human.device = human::HandDevice::Haptic;
    HumanBot person(options);
    Watched watched(person);
    const TrialResult r = playWatched("paper_reaching.lua", watched, seed);
    ASSERT_EQ(r.reason, script::trial_reason::kLeftFace) << "seed " << seed << ": the fall this test needs did not happen";
    EXPECT_TRUE(watched.warning) << "seed " << seed;
    const double lead = r.time - watched.lastOnset;
    EXPECT_GE(lead, 0.1) << "seed " << seed << ": warned at " << watched.lastOnset << " s, fell at " << r.time << " s";
    EXPECT_LE(lead, 1.0) << "seed " << seed << ": warned at " << watched.lastOnset << " s, fell at " << r.time << " s";
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
