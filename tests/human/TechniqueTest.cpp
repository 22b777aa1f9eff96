// engine/human/Technique: c_up read off the screen agrees with the
// autopilot's (an independent formula), and the decisions are the
// technique's: stir far from the target, aim to the side the hemisphere
// turns, let the stir die away near it, then hold; lean for a lean.

#include "engine/human/Technique.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/autopilot/UprightContact.h"
#include "engine/physics/HemisphereParams.h"
#include "engine/physics/Orientation.h"

namespace hemiroll::human {
namespace {

using physics::Vec2;
using physics::Vec3;

ScreenView viewOf(const physics::ForceDrivenState& x) {
  ScreenView v;
  v.contact = Vec2(x[7], x[8]);
  v.normal = physics::makeOrientation(x[9], x[10], x[11]).faceNormal();
  v.spin = x[6];
  return v;
}

TEST(Technique, TheUprightContactSeenIsTheAutopilots) {
  physics::HemisphereParams params;
  const physics::ModelConstants constants(params);
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  x[7] = 0.013, x[8] = -0.021, x[9] = 0.31, x[10] = -0.17, x[11] = 1.3;
  const Vec2 seen = uprightContactSeen(viewOf(x), params.radius);
  const Vec2 truth = autopilot::uprightContact(constants, x).point;
  EXPECT_LT((seen - truth).norm(), 1e-12);
}

TEST(Technique, FarFromTheTargetItSwirlsRoundWhereItWouldStandAimingToTheSideTheHemisphereTurns) {
  TechniqueDef def;
  ScreenView v;
  v.contactTargetSet = true;
  v.uprightRequired = true;
  v.contactTarget = Vec2(0.05, 0.0);
  for (const double spin : {0.3, -0.3}) {
    Technique t(def, 0.04);
    v.spin = spin;
    Movement m;
    for (int i = 0; i < 8; ++i) m = t.decide(v, 0.25);  // long enough to tell the sense
    EXPECT_EQ(m.kind, Movement::Kind::Stir);
    EXPECT_GT(m.rate, 0.0);  // the swirl goes anticlockwise
    const Vec2 aim = m.centre - v.contact;  // upright: c_up is the contact
    EXPECT_NEAR(aim.norm(), def.aimLimit, 1e-12);
    EXPECT_NEAR(std::atan2(aim.y(), aim.x()), spin > 0 ? def.aimAngle : -def.aimAngle, 1e-12);
  }
}

// The swirl's size follows the tilt gauge: it grows from the first size
// while the hemisphere leans less than swirlTilt, and shrinks while it
// leans more, within its limits.
TEST(Technique, TheSwirlGrowsWhileTheTiltIsShortOfTenDegreesAndShrinksBeyond) {
  TechniqueDef def;
  ScreenView v;
  v.contactTargetSet = true;
  v.uprightRequired = true;
  v.contactTarget = Vec2(0.05, 0.0);
  Technique t(def, 0.04);
  Movement m = t.decide(v, 0.25);
  double last = m.radius;
  EXPECT_GT(last, def.stirRadius);  // upright: it grows from the first decision
  for (int i = 0; i < 40; ++i) {
    m = t.decide(v, 0.25);
    EXPECT_GE(m.radius, last);
    last = m.radius;
  }
  EXPECT_DOUBLE_EQ(last, def.swirlMax);
  const double lean = 2.0 * def.swirlTilt;  // leaning twice as far: shrinks
  v.normal = Vec3(std::sin(lean), 0.0, std::cos(lean));
  v.contact = Vec2(0.04 * lean, 0.0);  // c_up stays at the origin, far from the target
  for (int i = 0; i < 40; ++i) {
    m = t.decide(v, 0.25);
    EXPECT_LE(m.radius, last + 1e-15);
    last = m.radius;
  }
  EXPECT_LT(last, 0.5 * def.swirlMax);
  EXPECT_GE(last, def.swirlMin);
}

TEST(Technique, NearTheTargetTheStirDiesAwayThenTheHandHoldsOverTheSpot) {
  TechniqueDef def;
  Technique t(def, 0.04);
  ScreenView v;
  v.contactTargetSet = true;
  v.uprightRequired = true;
  v.contactTarget = Vec2(0.0005, 0.0);  // within landReach of c_up (the origin, upright)
  double last = def.swirlMax;
  Movement m;
  for (int i = 0; i < 40 && t.phase() != Technique::Phase::Settle; ++i) {
    m = t.decide(v, 0.25);
    if (m.kind == Movement::Kind::Stir) {
      EXPECT_LE(m.radius, last + 1e-15);
      last = m.radius;
    }
  }
  EXPECT_EQ(t.phase(), Technique::Phase::Settle);
  m = t.decide(v, 0.25);
  EXPECT_EQ(m.kind, Movement::Kind::Hold);
  EXPECT_LT((m.centre - v.contactTarget).norm(), def.holdReach + 1e-9);
}

TEST(Technique, ALeanTheTaskAsksForIsHeldTheWayTheLeanShouldGo) {
  Technique t(TechniqueDef{}, 0.04);
  ScreenView v;
  v.leanTargetSet = true;
  v.leanTarget = Vec3(std::sin(0.08), 0.0, std::cos(0.08));  // 0.08 rad towards +x
  const Movement m = t.decide(v, 0.25);
  EXPECT_EQ(t.phase(), Technique::Phase::Lean);
  EXPECT_EQ(m.kind, Movement::Kind::Hold);
  EXPECT_GT(m.centre.x(), 0.0);
  EXPECT_NEAR(m.centre.y(), 0.0, 1e-12);
}

TEST(Technique, AHeadingToReachIsTurnedByAStirOnTheSpotThenItSettles) {
  TechniqueDef def;
  ScreenView v;
  v.contact = Vec2(0.001, -0.002);
  v.uprightRequired = true;
  v.leanTargetSet = true;  // upright, as tutorial 03's last stage asks
  v.headingSet = true;
  v.headingTolerance = 0.1;
  for (const double error : {-0.15, 0.15}) {  // clockwise still to go, then anticlockwise
    Technique t(def, 0.04);
    v.headingError = error;
    const Movement m = t.decide(v, 0.25);
    EXPECT_EQ(t.phase(), Technique::Phase::Turn);
    EXPECT_EQ(m.kind, Movement::Kind::Stir);
    EXPECT_EQ(m.centre, v.contact);  // on the spot: no aim
    EXPECT_DOUBLE_EQ(m.radius, def.stirRadius);
    EXPECT_DOUBLE_EQ(m.rate, error < 0.0 ? def.stirRate : -def.stirRate);  // anticlockwise turns it clockwise
  }
  // Well inside the band: the stir dies away in the sense it had, then the hand holds.
  Technique t(def, 0.04);
  v.headingError = -0.15;
  t.decide(v, 0.25);
  v.headingError = -0.01;
  Movement m = t.decide(v, 0.25);
  EXPECT_EQ(t.phase(), Technique::Phase::Land);
  EXPECT_GT(m.rate, 0.0);
  for (int i = 0; i < 40 && t.phase() != Technique::Phase::Settle; ++i) m = t.decide(v, 0.25);
  EXPECT_EQ(t.phase(), Technique::Phase::Settle);
  EXPECT_EQ(m.kind, Movement::Kind::Hold);
  // Pushed out of its band again while settling: turn again.
  v.headingError = 0.095;
  t.decide(v, 0.25);
  EXPECT_EQ(t.phase(), Technique::Phase::Turn);
}

// Settled on the target but still turning faster than the HUD's band
// allows: a swirl of the settled size in the sense it turns, on the spot,
// for brakeTime; then it dies away and the hand holds again.
TEST(Technique, SettledButTurningItBrakesWithASwirlInTheSenseItTurnsThenSettles) {
  TechniqueDef def;
  for (const double spin : {-0.026, 0.08}) {
    Technique t(def, 0.04);
    ScreenView v;
    v.contactTargetSet = true;
    v.uprightRequired = true;
    v.contactTarget = Vec2(0.0005, 0.0);
    v.spinTolerance = 0.01;  // the paper's band: brake above half of it
    for (int i = 0; i < 40 && t.phase() != Technique::Phase::Settle; ++i) t.decide(v, 0.25);
    ASSERT_EQ(t.phase(), Technique::Phase::Settle);
    v.spin = spin;
    Movement m;
    double time = v.time;
    // Not before brakeWait settled.
    m = t.decide(v, 0.25);
    EXPECT_EQ(m.kind, Movement::Kind::Hold);
    for (int i = 0; i < 20 && t.phase() == Technique::Phase::Settle; ++i) {
      v.time = time += 0.25;
      m = t.decide(v, 0.25);
    }
    ASSERT_EQ(t.phase(), Technique::Phase::Brake);
    EXPECT_EQ(m.kind, Movement::Kind::Stir);
    EXPECT_EQ(m.rate > 0.0, spin > 0.0);  // the sense it turns
    EXPECT_GE(m.radius, def.swirlMin);
    EXPECT_LT((m.centre - v.contact).norm(), 1e-3);  // on the spot: c_up, watched
    const double size = m.radius;
    double last = size;
    for (int i = 0; i < 40 && t.phase() == Technique::Phase::Brake; ++i) {
      v.time = time += 0.25;
      m = t.decide(v, 0.25);
      if (m.kind == Movement::Kind::Stir) {
        EXPECT_LE(m.radius, last + 1e-15);
        last = m.radius;
      }
    }
    EXPECT_EQ(t.phase(), Technique::Phase::Settle);
    EXPECT_EQ(m.kind, Movement::Kind::Hold);
    // Turning within the band's half: no brake.
    v.spin = 0.004;
    for (int i = 0; i < 20; ++i) {
      v.time = time += 0.25;
      t.decide(v, 0.25);
      EXPECT_NE(t.phase(), Technique::Phase::Brake);
    }
  }
}

}  // namespace
}  // namespace hemiroll::human
