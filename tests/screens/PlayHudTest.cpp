#include "game/hud/PlayHud.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/physics/StateKinematics.h"
#include "engine/script/LevelLoader.h"

namespace hemiroll::game {
namespace {

struct Fixture {
  script::LoadedLevel level = script::LevelLoader().loadFile(HEMIROLL_SOURCE_DIR "/levels/paper_reaching.lua");
  script::TaskJudge judge{level.def.task};
  haptics::ServoSnapshot snapshot;

  void judgeAt(double time) {
    snapshot.time = time;
    script::JudgeInput in;
    in.time = time;
    in.state = physics::forceStateOf(snapshot.state);
    judge.judge(in);
  }
};

TEST(PlayHudTest, ReadsTimeDistanceAndComponentsFromTheJudge) {
  Fixture f;
  for (int i = 0; i < 12; ++i) f.snapshot.state[static_cast<std::size_t>(i)] = f.level.def.initial[i];
  f.judgeAt(1.0);
  PlayHud hud;
  hud.update(f.snapshot, f.judge);
  const HudReadout& r = hud.readout();
  EXPECT_EQ(r.time, 1.0);
  EXPECT_EQ(r.timeLimit, f.level.def.task.timeLimit);
  double du = 0.0, dv = 0.0;
  int inside = 0;
  for (const script::ComponentStatus& c : f.judge.components()) {
    if (c.variable == script::TaskVariable::u_a) du = c.error;
    if (c.variable == script::TaskVariable::v_a) dv = c.error;
    inside += c.inside;
  }
  ASSERT_GT(std::hypot(du, dv), 0.0);  // the paper's target is 5.7 cm from the start
  EXPECT_DOUBLE_EQ(r.distanceToTarget, std::hypot(du, dv));
  EXPECT_EQ(r.components, static_cast<int>(f.judge.components().size()));
  EXPECT_EQ(r.componentsInside, inside);
  EXPECT_FALSE(r.loopWarning);
  EXPECT_EQ(hud.plot().size(), 1u);
}

TEST(PlayHudTest, WarnsAboutMissedOrLateTicks) {
  Fixture f;
  f.judgeAt(0.5);
  PlayHud hud;
  f.snapshot.missedTicks = 3;
  hud.update(f.snapshot, f.judge);
  EXPECT_TRUE(hud.readout().loopWarning);
  EXPECT_EQ(hud.readout().missedTicks, 3u);
  f.snapshot.missedTicks = 0;
  f.snapshot.lateness = 2 * PlayHud::kLateWarning;
  f.snapshot.time = 0.6;
  hud.update(f.snapshot, f.judge);
  EXPECT_TRUE(hud.readout().loopWarning);
  f.snapshot.lateness = 0.0;
  f.snapshot.time = 0.7;
  hud.update(f.snapshot, f.judge);
  EXPECT_FALSE(hud.readout().loopWarning);
}

TEST(PlayHudTest, PrecessionIsTheHeadingsRateAcrossTheWrap) {
  Fixture f;
  PlayHud hud;
  f.snapshot.state[physics::force_slot::psi] = 3.1;
  f.judgeAt(1.0);
  hud.update(f.snapshot, f.judge);
  // psi goes 3.1 -> -3.1 (0.083 rad forward across pi) in 0.1 s.
  f.snapshot.state[physics::force_slot::psi] = -3.1;
  f.judgeAt(1.1);
  hud.update(f.snapshot, f.judge);
  const double expected = (2.0 * M_PI - 6.2) / 0.1;
  EXPECT_NEAR(hud.readout().precessionRate, expected, 1e-9);  // rounding of the two times only
}

TEST(PlayHudTest, AFrameWithoutANewTickAddsNoPlotSample) {
  Fixture f;
  PlayHud hud;
  f.judgeAt(0.2);
  hud.update(f.snapshot, f.judge);
  hud.update(f.snapshot, f.judge);  // paused: the same snapshot time
  EXPECT_EQ(hud.plot().size(), 1u);
  hud.setChannel(2);
  EXPECT_EQ(hud.plot().size(), 0u);  // a new channel starts a new trace
}

TEST(PlayHudTest, MessagesKeepTheNewestFewAndResetClearsThem) {
  PlayHud hud;
  for (std::size_t i = 0; i < PlayHud::kMessages + 2; ++i) {
    std::string text = "m";  // (not "m" + to_string: GCC 12's -Wrestrict false positive)
    text += std::to_string(i);
    hud.addMessage(text, 10.0);
  }
  EXPECT_EQ(hud.messages(1.0).size(), PlayHud::kMessages);
  EXPECT_EQ(hud.messages(1.0).front(), "m2");  // the two oldest gave way
  EXPECT_TRUE(hud.messages(11.0).empty());     // expired
  hud.reset();
  EXPECT_TRUE(hud.messages(1.0).empty());
}

}  // namespace
}  // namespace hemiroll::game
