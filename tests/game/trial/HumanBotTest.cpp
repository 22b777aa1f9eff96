// game/trial/HumanBot through the real trial loop (BotTrial: servo
// loop, coupling, ramp, safety, judge): the simulated person wins the first
// two tutorials as a person with a mouse does, plays the same per seed, and
// sees the task as the screen shows it.

#include "game/trial/HumanBot.h"

#include <gtest/gtest.h>

#include <string>

#include "engine/script/LevelLoader.h"
#include "game/trial/BotTrial.h"

namespace hemiroll::game {
namespace {

using task::TrialOutcome;

const std::string kLevels = std::string(HEMIROLL_SOURCE_DIR) + "/levels/";

TrialResult play(const std::string& file, std::uint64_t seed, const HumanBotOptions& options = {}) {
  script::LevelLoadOptions loadOptions;
  loadOptions.seed = seed;
  script::LoadedLevel level = script::LevelLoader(loadOptions).loadFile(kLevels + file);
  HumanBot bot(options);
  TrialSettings settings;
  settings.seed = seed;
  return BotTrial(level, bot, settings).run();
}

// A person is not a machine: judged over seeds, at the model's floor (the
// default delay, interval and noise: HumanDef::kMin*, kDefaultNoise). The
// rates measured over 20 seeds are in docs/HUMAN_MODEL.md; 4 of 5 is the
// floor of what they allow.
void expectMostlyWon(const std::string& file) {
  int won = 0;
  std::string lost;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const TrialResult r = play(file, seed);
    if (r.outcome == TrialOutcome::Success) ++won;
    else lost += " seed " + std::to_string(seed) + ": " + r.reason + ";";
  }
  EXPECT_GE(won, 4) << file << lost;
}

TEST(HumanBot, WinsTutorialOneOnAMouse) { expectMostlyWon("tutorial_01_tilt_and_return.lua"); }

TEST(HumanBot, WinsTutorialTwoOnAMouse) { expectMostlyWon("tutorial_02_roll_a_short_distance.lua"); }

// The swirl carries c_up 2 cm and the brake takes the last turning out
// (Technique: Stir, Land, Settle, Brake): measured 19-20 of 20.
TEST(HumanBot, WinsTutorialFiveOnAMouse) { expectMostlyWon("tutorial_05_helix.lua"); }

// The paper's task by sight alone, with the technique learnt in words:
// measured 20 of 20 at 0.2 s (docs/HUMAN_MODEL.md).
TEST(HumanBot, WinsThePapersTaskOnAMouse) { expectMostlyWon("paper_reaching.lua"); }

// On a force device (M3, alpha 2) the co-contracted arm keeps the mass
// point on the face and wins the paper's task: measured 33 of 40 seeds
// (docs/HUMAN_MODEL.md), every loss at the time limit; the relaxed arm
// (300 N/m in series with the 250 N/m coupling) lets it off the face in
// every seed, after 2.7-7.0 s over 40 seeds (3.2-5.2 s in seeds 1-3). 3 of
// 5 is the floor the measured rate allows.
TEST(HumanBot, OnAForceDeviceTheCoContractedArmKeepsTheMassPointOnTheFace) {
  HumanBotOptions haptic;
  haptic.human.device = human::HandDevice::Haptic;
  HumanBotOptions relaxed = haptic;
  relaxed.human.coContracts = false;
  int won = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const TrialResult r = play("paper_reaching.lua", seed, haptic);
    EXPECT_EQ(r.reason.find("left the face"), std::string::npos) << "seed " << seed << ": " << r.reason;
    EXPECT_GT(r.time, 60.0) << "seed " << seed;
    if (r.outcome == TrialOutcome::Success) ++won;
    if (seed > 3) continue;
    const TrialResult off = play("paper_reaching.lua", seed, relaxed);
    EXPECT_NE(off.reason.find("left the face"), std::string::npos) << "seed " << seed << ": " << off.reason;
    EXPECT_LT(off.time, 6.0) << "seed " << seed;
  }
  EXPECT_GE(won, 3);
}

// With the aids the person traces the hint's ring (HintSmoother: the
// technique worked out from the state now), and wins with it.
TEST(HumanBot, WithTheAidsItTracesTheHintsRingAndWinsTutorialFive) {
  script::LevelLoadOptions loadOptions;
  loadOptions.seed = 1;
  script::LoadedLevel level = script::LevelLoader(loadOptions).loadFile(kLevels + "tutorial_05_helix.lua");
  HumanBotOptions options;
  options.aids = true;
  HumanBot bot(options);
  TrialSettings settings;
  settings.seed = 1;
  const TrialResult r = BotTrial(level, bot, settings).run();
  EXPECT_EQ(r.outcome, TrialOutcome::Success) << r.reason;
  ASSERT_NE(bot.model(), nullptr);
  EXPECT_GT(bot.model()->stats().hintCorrections, 10);
}

// The hint drawn ahead (HintSmoother) wins the paper's task for a person a
// quarter second late: measured 20 of 20 on seeds 1-20 and 19 of 20 on
// 21-40 (docs/HUMAN_MODEL.md); drawn for now, with its centre low-passed
// over a second, it won seeds 1-5 only 3 times.
TEST(HumanBot, WithTheAidsItWinsThePapersTaskAQuarterSecondLate) {
  HumanBotOptions options;
  options.aids = true;
  options.human.visualDelay = 0.25;
  int won = 0;
  std::string lost;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const TrialResult r = play("paper_reaching.lua", seed, options);
    if (r.outcome == TrialOutcome::Success) ++won;
    else lost += " seed " + std::to_string(seed) + ": " + r.reason + ";";
  }
  EXPECT_GE(won, 4) << lost;
}

TEST(HumanBot, TheSameSeedPlaysTheSameTrialAndAnotherSeedAnother) {
  const TrialResult a = play("tutorial_01_tilt_and_return.lua", 3);
  const TrialResult b = play("tutorial_01_tilt_and_return.lua", 3);
  const TrialResult c = play("tutorial_01_tilt_and_return.lua", 4);
  EXPECT_EQ(a.ticks, b.ticks);
  EXPECT_EQ(a.time, b.time);
  EXPECT_NE(a.ticks, c.ticks);
}

// On the mouse-hand device the person's mouse pulls the game's simulated
// hand, which the force pushes: the same seed plays the same trial, and not
// the trial of the plain mouse (the hand is in the loop). It wins tutorial
// 01 as the mouse does (20 of 20 seeds, docs/HUMAN_MODEL.md).
TEST(HumanBot, OnTheMouseHandTheGamesHandSitsBetweenMouseAndProxy) {
  HumanBotOptions hand;
  hand.human.device = human::HandDevice::MouseHand;
  const TrialResult a = play("tutorial_01_tilt_and_return.lua", 3, hand);
  const TrialResult b = play("tutorial_01_tilt_and_return.lua", 3, hand);
  const TrialResult mouse = play("tutorial_01_tilt_and_return.lua", 3);
  EXPECT_EQ(a.outcome, TrialOutcome::Success) << a.reason;
  EXPECT_EQ(a.ticks, b.ticks);
  EXPECT_EQ(a.time, b.time);
  EXPECT_NE(a.ticks, mouse.ticks);
  HumanBotOptions bad = hand;
  bad.mouseHand.mass = 0.0;
  const TrialResult refused = play("tutorial_01_tilt_and_return.lua", 3, bad);
  EXPECT_EQ(refused.outcome, TrialOutcome::Failure);
  EXPECT_NE(refused.reason.find("mouse-hand: hand mass must be a positive number of kg"), std::string::npos)
      << refused.reason;
}

TEST(HumanBot, SeesTheTaskAsTheScreenShowsIt) {
  script::BotObservation obs;
  obs.time = 1.5;
  obs.contact = {0.01, -0.02, 0.0};
  obs.targetSet[7] = obs.targetSet[8] = true;
  obs.target[7] = -0.04;
  obs.target[8] = -0.04;
  obs.tolerance[7] = obs.tolerance[8] = 0.004;
  obs.targetSet[0] = true;  // a band on p: upright at the end
  obs.state[6] = 0.3;
  const human::ScreenView v = screenViewOf(obs);
  EXPECT_EQ(v.time, 1.5);
  EXPECT_EQ(v.contact, physics::Vec2(0.01, -0.02));
  EXPECT_TRUE(v.contactTargetSet);
  EXPECT_EQ(v.contactTarget, physics::Vec2(-0.04, -0.04));
  EXPECT_EQ(v.contactTolerance, 0.004);
  EXPECT_TRUE(v.uprightRequired);
  EXPECT_FALSE(v.leanTargetSet);
  EXPECT_EQ(v.spin, 0.3);
  EXPECT_EQ(v.spinTolerance, 0.0);  // no band on the spin
  EXPECT_EQ(v.hint.kind, human::HintKind::None);  // no aids unless asked for
  obs.targetSet[6] = true;  // a band on w_z, as the HUD gives it
  obs.tolerance[6] = 0.01;
  EXPECT_EQ(screenViewOf(obs).spinTolerance, 0.01);
  obs.targetSet[6] = false;
  obs.omegaNormSet = true;  // or on |omega|
  obs.omegaNormTolerance = 0.03;
  EXPECT_EQ(screenViewOf(obs).spinTolerance, 0.03);
}

TEST(HumanBot, ALeanTheTaskAsksForIsShownAsTheNormalItWouldHave) {
  script::BotObservation obs;
  obs.targetSet[9] = true;
  obs.target[9] = -0.08;  // u_o: the tutorial's lean towards +x
  obs.tolerance[9] = 0.03;
  const human::ScreenView v = screenViewOf(obs);
  ASSERT_TRUE(v.leanTargetSet);
  EXPECT_NEAR(v.leanTarget.x(), std::sin(0.08), 1e-12);
  EXPECT_NEAR(v.leanTarget.y(), 0.0, 1e-12);
  EXPECT_EQ(v.leanTolerance, 0.03);
}

TEST(HumanBot, AHeadingTheTaskAsksForIsShownAsTheHudSaysIt) {
  script::BotObservation obs;
  EXPECT_FALSE(screenViewOf(obs).headingSet);
  obs.targetSet[11] = true;
  obs.target[11] = -0.15;  // psi: tutorial 03's turn
  obs.tolerance[11] = 0.1;
  obs.state[11] = 0.05;
  human::ScreenView v = screenViewOf(obs);
  ASSERT_TRUE(v.headingSet);
  EXPECT_NEAR(v.headingError, -0.2, 1e-12);  // target - value: clockwise still to go
  EXPECT_EQ(v.headingTolerance, 0.1);
  obs.state[11] = -0.15 + 2.0 * M_PI - 0.01;  // a turn and a bit the other way: the short way round
  v = screenViewOf(obs);
  EXPECT_NEAR(v.headingError, 0.01, 1e-12);
}

// In a session the person learns: each trial's init reads the trials
// practised from the participant's memory, plays with the noise the law of
// practice gives for them, and counts one more. Outside a session (no
// memory) the noise is the model's own.
TEST(HumanBot, InASessionEachTrialPractisesAndLowersTheNoiseByTheLawOfPractice) {
  script::LevelLoadOptions loadOptions;
  script::LoadedLevel level = script::LevelLoader(loadOptions).loadFile(kLevels + "tutorial_01_tilt_and_return.lua");
  script::BotMemory memory;
  script::BotLevelInfo info;
  info.params = level.def.params;
  info.memory = &memory;
  HumanBotOptions options;
  for (int trial = 0; trial < 4; ++trial) {
    HumanBot bot(options);
    bot.init(info, 7);
    ASSERT_NE(bot.model(), nullptr);
    EXPECT_DOUBLE_EQ(bot.model()->def().noise, human::practisedNoise(options.practice, options.human.noise, trial));
    EXPECT_EQ(memory.get(kPracticeTrials), trial + 1.0);
    EXPECT_EQ(memory.get(kMotorNoise), bot.model()->def().noise);
  }
  info.memory = nullptr;
  HumanBot outside(options);
  outside.init(info, 7);
  EXPECT_EQ(outside.model()->def().noise, options.human.noise);
  options.learns = false;
  info.memory = &memory;
  HumanBot fixed(options);
  fixed.init(info, 7);
  EXPECT_EQ(fixed.model()->def().noise, options.human.noise);
  EXPECT_EQ(memory.get(kPracticeTrials), 4.0);  // a person who does not learn counts nothing
}

}  // namespace
}  // namespace hemiroll::game
