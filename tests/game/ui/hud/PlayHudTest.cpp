#include "game/ui/hud/PlayHud.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/physics/Energy.h"
#include "engine/physics/StateKinematics.h"
#include "engine/script/LevelLoader.h"

namespace hemiroll::game {
namespace {

struct Fixture {
  script::LoadedLevel level = script::LevelLoader().loadFile(HEMIROLL_SOURCE_DIR "/levels/paper_reaching.lua");
  task::TaskJudge judge{level.def.task};
  haptics::ServoSnapshot snapshot;

  void judgeAt(double time) {
    snapshot.time = time;
    task::JudgeInput in;
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
  for (const task::ComponentStatus& c : f.judge.components()) {
    if (c.variable == task::TaskVariable::u_a) du = c.error;
    if (c.variable == task::TaskVariable::v_a) dv = c.error;
    inside += c.inside;
  }
  ASSERT_GT(std::hypot(du, dv), 0.0);  // the paper's target is 5.7 cm from the start
  EXPECT_DOUBLE_EQ(r.distanceToTarget, std::hypot(du, dv));
  EXPECT_EQ(r.components, static_cast<int>(f.judge.components().size()));
  EXPECT_EQ(r.componentsInside, inside);
  EXPECT_FALSE(r.loopWarning);
  EXPECT_EQ(hud.plot(0).size(), 1u);
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
  EXPECT_EQ(hud.plot(0).size(), 1u);
}

// scene.plots decides the plots (at most three), each in its player unit;
// a level without plots gets the contact point's x and y.
TEST(PlayHudTest, PlotsAreTheLevelsChannelsInPlayerUnits) {
  Fixture f;
  PlayHud hud;
  EXPECT_EQ(hud.plotCount(), 2u);
  EXPECT_STREQ(hud.plotChannel(0).unit().label, "contact x");
  EXPECT_STREQ(hud.plotChannel(1).unit().label, "contact y");

  hud.setPlots({"u_o", "x_p", "energy", "force_norm"}, f.level.def.params);
  ASSERT_EQ(hud.plotCount(), PlayHud::kMaxPlots);
  EXPECT_STREQ(hud.plotChannel(0).unit().unit, "°");
  EXPECT_STREQ(hud.plotChannel(1).unit().unit, "mm");
  EXPECT_STREQ(hud.plotChannel(2).unit().label, "energy");
  f.snapshot.state.fill(0.0);
  f.snapshot.state[physics::force_slot::u_o] = -0.08;
  f.snapshot.state[physics::force_slot::x_p] = 0.015;
  f.judgeAt(0.1);
  hud.update(f.snapshot, f.judge);
  EXPECT_FLOAT_EQ(hud.plot(0).at(0), static_cast<float>(-0.08 * 180.0 / M_PI));
  EXPECT_FLOAT_EQ(hud.plot(1).at(0), 15.0f);
  const double energy =
      physics::mechanicalEnergy(physics::RollingDynamics(f.level.def.params), physics::forceStateOf(f.snapshot.state))
          .total();
  EXPECT_FLOAT_EQ(hud.plot(2).at(0), static_cast<float>(energy * 1e3));
}

// Every channel a level may name (docs/LEVELS.md, "Plot channels") is one
// the HUD can draw, in a unit of its own; anything else is not.
TEST(PlayHudTest, EveryPlotChannelALevelMayNameHasAPlayerUnit) {
  for (const char* name : {"x_p", "y_p", "xd_p", "yd_p", "w_x", "w_y", "w_z", "u_a", "v_a", "u_o", "v_o", "psi",
                           "omega_norm", "energy", "proxy_x", "proxy_y", "proxy_z", "force_x", "force_y", "force_z",
                           "force_norm"}) {
    const std::optional<HudChannel> c = HudChannel::fromName(name);
    ASSERT_TRUE(c.has_value()) << name;
    EXPECT_GT(c->unit().scale, 0.0) << name;
  }
  EXPECT_FALSE(HudChannel::fromName("proxy_w").has_value());
  EXPECT_FALSE(HudChannel::fromName("u_ca").has_value());  // a group, not a channel
  haptics::ServoSnapshot s;
  s.proxyPosition = {0.01, 0.02, 0.03};
  s.handForce = {3.0, 4.0, 0.0};
  const physics::RollingDynamics dynamics{physics::HemisphereParams{}};
  EXPECT_EQ(HudChannel::fromName("proxy_y")->value(s, dynamics), 0.02);
  EXPECT_EQ(HudChannel::fromName("force_norm")->value(s, dynamics), 5.0);
}

// Measured in play: a contact-x plot from 0.05 to 0.1 mm read "+0.1" at both ends.
TEST(PlayHudTest, PlotAxesGetTheDecimalsThatTellTheirEndsApart) {
  EXPECT_EQ(PlayHud::axisDecimals(2.0), 1);
  EXPECT_EQ(PlayHud::axisDecimals(1.0), 1);
  EXPECT_EQ(PlayHud::axisDecimals(0.05), 3);  // 0.05 .. 0.10 reads +0.050 .. +0.100
  EXPECT_EQ(PlayHud::axisDecimals(0.5), 2);
  EXPECT_EQ(PlayHud::axisDecimals(1e-9), 3);
  EXPECT_EQ(PlayHud::axisDecimals(0.0), 1);
  EXPECT_EQ(PlayHud::axisDecimals(std::nan("")), 1);
  // An axis end of -0.01 at one decimal reads +0.0, not -0.0 (seen in play).
  char label[16];
  std::snprintf(label, sizeof label, "%+.*f", 1, PlayHud::shownAs(-0.01, 1));
  EXPECT_STREQ(label, "+0.0");
  EXPECT_EQ(PlayHud::shownAs(-0.06, 1), -0.06);
}

// The full table keeps the physics' names, with the value and what it
// wants (not their difference, which the player had to negate).
TEST(PlayHudTest, TheTableReadsValuesAndTargetsInPlayerUnits) {
  task::ComponentStatus c;
  c.variable = task::TaskVariable::u_a;
  c.target = -0.04;
  c.error = 0.0123;
  c.tolerance = 0.001;
  EXPECT_EQ(PlayHud::componentLine(c), "contact x (u_a) -27.7 mm, wants -40.0 ±1.0 mm");
  c.variable = task::TaskVariable::u_o;  // a band under a degree gets two decimals
  c.target = 0.0;
  c.error = -0.02;
  c.tolerance = 0.01;
  EXPECT_EQ(PlayHud::componentLine(c), "tilt u (u_o) -1.15 °, wants +0.00 ±0.57 °");
  task::HoldBreak b;
  b.happened = true;
  b.variable = task::TaskVariable::xd_p;
  b.excess = 0.0042;
  b.heldFor = 0.6;
  EXPECT_EQ(PlayHud::holdBreakLine(b), "the mass point speed went out by 4.2 mm/s after 0.6 s");
}

// The settle meter's readout: the judge's hold and its last break; the tilt
// gauge's: the face normal's angle and the way it leans.
TEST(PlayHudTest, ReadsTheHoldItsLastBreakAndTheTilt) {
  script::LoadedLevel level = script::LevelLoader().loadFile(HEMIROLL_SOURCE_DIR "/levels/tutorial_01_tilt_and_return.lua");
  task::TaskJudge judge(level.def.task);
  haptics::ServoSnapshot s;
  s.state[physics::force_slot::u_o] = -0.08;  // the first stage's target: leaning towards +x
  auto judgeAt = [&](double t) {
    s.time = t;
    task::JudgeInput in;
    in.time = t;
    in.state = physics::forceStateOf(s.state);
    judge.judge(in);
  };
  PlayHud hud;
  judgeAt(0.1);
  judgeAt(0.3);
  hud.update(s, judge);
  EXPECT_TRUE(hud.readout().allInside);
  EXPECT_NEAR(hud.readout().holdTime, 0.2, 1e-12);
  EXPECT_NEAR(hud.readout().tilt.angle, 0.08, 1e-12);
  EXPECT_NEAR(hud.readout().tilt.downhillX, 1.0, 1e-12);
  EXPECT_NEAR(hud.readout().tilt.downhillY, 0.0, 1e-12);
  s.state[physics::force_slot::u_o] = 0.0;  // out of the band by 0.05 rad
  judgeAt(0.35);
  hud.update(s, judge);
  EXPECT_FALSE(hud.readout().allInside);
  ASSERT_TRUE(hud.readout().holdBreak.happened);
  EXPECT_EQ(hud.readout().holdBreak.variable, task::TaskVariable::u_o);
  EXPECT_NEAR(hud.readout().holdBreak.excess, 0.05, 1e-12);
  EXPECT_EQ(hud.readout().tilt.angle, 0.0);
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
