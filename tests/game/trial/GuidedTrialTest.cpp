// Haptic guidance in a whole trial (game/trial): the autopilot's plan as a
// spring-damper on the device, felt by the built-in passive hand, which
// moves only where the device pushes it. Headless and deterministic.

#include <gtest/gtest.h>

#include <string>

#include "engine/script/BotScript.h"
#include "engine/script/LevelLoader.h"
#include "game/trial/BotTrial.h"
#include "game/trial/PassiveHandBot.h"

namespace hemiroll::game {
namespace {

const std::string kLevels = std::string(HEMIROLL_SOURCE_DIR) + "/levels/";

TrialResult passiveHandOn(const std::string& level, haptics::GuidanceKind kind, double stiffness = 300.0) {
  script::LoadedLevel loaded = script::LevelLoader().loadFile(kLevels + level);
  PassiveHandBot hand;
  TrialSettings settings;
  settings.guidance.kind = kind;
  settings.guidance.stiffness = stiffness;
  settings.guidance.damping = 10.0;
  return BotTrial(loaded, hand, settings).run();
}

// The passive hand on its own: still without force, and under a steady push
// the relaxed arm's drift reaches its steady state. In continuous time the
// arm's spring then stretches by v tau and F = k v tau + b v. The bot's
// semi-implicit Euler moves the rest after the hand within a tick, so the
// stretch the force sees is v (tau - dt): v = F / (k (tau - dt) + b), the
// continuous rate to within dt / tau = 0.1 %.
TEST(PassiveHandTest, StillWithoutForceAndDriftingAtTheSteadyRateUnderAPush) {
  const PassiveHandDef def;
  PassiveHandBot hand(def);
  script::BotLevelInfo info;
  info.dt = 0.001;
  hand.init(info, 0);
  script::BotObservation obs;
  obs.mass = {0.01, -0.02, 0.04};
  script::BotAction a;
  for (int tick = 0; tick <= 1000; ++tick) {
    obs.time = tick * info.dt;
    a = hand.act(obs);
  }
  EXPECT_EQ(a.position, obs.mass);  // no force: it holds where it took hold
  const double push = 0.3;          // [N] along y
  obs.deviceForce = {0.0, push, 0.0};
  for (int tick = 1001; tick <= 30000; ++tick) {
    obs.time = tick * info.dt;
    a = hand.act(obs);
  }
  const double steady = push / (def.stiffness * (def.settleTime - info.dt) + def.damping);
  // The velocity and the arm's stretch settle as a damped pair with real part
  // -(b/m + 1/tau)/2 = -17 /s: after 29 s, far below rounding.
  EXPECT_NEAR(a.velocity[1], steady, 1e-9 * steady);
  EXPECT_NEAR(a.velocity[1], push / (def.stiffness * def.settleTime + def.damping), 1.1e-3 * steady);
  EXPECT_EQ(a.velocity[0], 0.0);
  EXPECT_GT(a.position[1], obs.mass[1] + 0.9 * steady * 28.0);
}

// The paper's task in miniature (tutorial 04): a hand that only yields to
// the device reaches the target and stops there when the autopilot guides
// it, and not without guidance or with the error pushed up.
TEST(GuidedTrialTest, AutopilotGuidanceLeadsAPassiveHandToTheTarget) {
  const TrialResult guided = passiveHandOn("tutorial_04_stop_on_target.lua", haptics::GuidanceKind::Autopilot);
  EXPECT_EQ(guided.outcome, task::TrialOutcome::Success) << guided.reason;
  const TrialResult alone = passiveHandOn("tutorial_04_stop_on_target.lua", haptics::GuidanceKind::None);
  EXPECT_EQ(alone.outcome, task::TrialOutcome::Failure);
  EXPECT_EQ(alone.reason, "time limit reached");
  const TrialResult augmented =
      passiveHandOn("tutorial_04_stop_on_target.lua", haptics::GuidanceKind::ErrorAugmentation);
  EXPECT_EQ(augmented.outcome, task::TrialOutcome::Failure);
}

TEST(GuidedTrialTest, AGuidedTrialIsDeterministic) {
  const TrialResult a = passiveHandOn("tutorial_02_roll_a_short_distance.lua", haptics::GuidanceKind::Autopilot);
  const TrialResult b = passiveHandOn("tutorial_02_roll_a_short_distance.lua", haptics::GuidanceKind::Autopilot);
  EXPECT_EQ(a.outcome, task::TrialOutcome::Success) << a.reason;
  EXPECT_EQ(a.ticks, b.ticks);
  EXPECT_EQ(a.time, b.time);
}

// scripts/lib/arm.lua gives Lua bots the passive hand's arm: the shipped
// scripts/bots/compliant.lua, which only yields, plays a guided trial to
// the same end on the same tick as the built-in passive hand.
TEST(GuidedTrialTest, ALuaBotWithTheCompliantArmFeelsGuidanceAsThePassiveHandDoes) {
  const TrialResult builtin = passiveHandOn("tutorial_02_roll_a_short_distance.lua", haptics::GuidanceKind::Autopilot);
  script::LoadedLevel loaded = script::LevelLoader().loadFile(kLevels + "tutorial_02_roll_a_short_distance.lua");
  script::BotScript lua(std::string(HEMIROLL_SOURCE_DIR) + "/scripts/bots/compliant.lua");
  TrialSettings settings;
  settings.guidance.kind = haptics::GuidanceKind::Autopilot;
  settings.guidance.stiffness = 300.0;
  settings.guidance.damping = 10.0;
  const TrialResult withArm = BotTrial(loaded, lua, settings).run();
  EXPECT_EQ(withArm.outcome, builtin.outcome) << withArm.reason;
  EXPECT_EQ(withArm.ticks, builtin.ticks);
  EXPECT_EQ(withArm.outcome, task::TrialOutcome::Success) << withArm.reason;  // guidance led it there
}

}  // namespace
}  // namespace hemiroll::game
