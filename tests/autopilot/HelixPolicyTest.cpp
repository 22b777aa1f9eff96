// engine/autopilot/HelixPolicy: the law's three phases as HelixPolicy.h
// states them, on a still state (so that each tick's proxy is the law's
// alone): the circle's radius, pace and steering offset while travelling, the
// radius fading at landRate while landing, the glide's speed limit while
// settling; and a copy continues bit for bit (the planner rolls copies).

#include "engine/autopilot/HelixPolicy.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/autopilot/UprightContact.h"
#include "engine/physics/StateLayout.h"

namespace hemiroll::autopilot {
namespace {

using physics::Vec2;
using physics::Vec3;

constexpr double kDt = 0.001;

struct Fixture {
  physics::HemisphereParams params;
  physics::ModelConstants constants{params};
  // Upright and still, the contact at (0.01, 0.02).
  physics::ForceDrivenState x = [] {
    physics::ForceDrivenState s = physics::ForceDrivenState::Zero();
    s[physics::force_slot::u_a] = 0.01;
    s[physics::force_slot::v_a] = 0.02;
    return s;
  }();
};

Goal contactGoal(double u, double v) {
  Goal g;
  g.set[7] = g.set[8] = true;
  g.target[7] = u;
  g.target[8] = v;
  g.tolerance[7] = g.tolerance[8] = 0.004;
  return g;
}

TEST(HelixPolicy, TravelCirclesTheSteeringPointAtItsRadiusAndPace) {
  Fixture f;
  HelixParams p;
  HelixPolicy law(f.constants, p, kDt);
  const Vec2 here = uprightContact(f.constants, f.x).point;
  law.setGoal(contactGoal(here.x(), here.y()));  // no error: no steering offset
  law.startAt(Vec3(0.01, 0.02, f.params.radius));
  // The radius grows to `amplitude` at amplitude per second: 1 s.
  Vec3 proxy;
  for (int k = 0; k < 1100; ++k) proxy = law.proxyFor(f.x);
  const Vec2 centre(0.01, 0.02);
  EXPECT_NEAR((proxy.head<2>() - centre).norm(), p.amplitude, 1e-12);
  EXPECT_DOUBLE_EQ(proxy.z(), f.params.radius);
  EXPECT_EQ(law.motion().phase, HelixPhase::Travel);
  EXPECT_NEAR((law.motion().centre - centre).norm(), 0.0, 1e-15);
  // One tick turns the proxy by rate x dt about the centre.
  const Vec3 next = law.proxyFor(f.x);
  const double a0 = std::atan2(proxy.y() - centre.y(), proxy.x() - centre.x());
  const double a1 = std::atan2(next.y() - centre.y(), next.x() - centre.x());
  EXPECT_NEAR(std::remainder(a1 - a0, 2.0 * M_PI), p.rate * kDt, 1e-9);
}

TEST(HelixPolicy, TheSteeringOffsetIsTheErrorTurnedAndLimited) {
  Fixture f;
  HelixParams p;
  p.steerGain = 0.1;
  p.steerLimit = 0.0015;
  p.steerAngle = M_PI / 2;
  HelixPolicy law(f.constants, p, kDt);
  const Vec2 here = uprightContact(f.constants, f.x).point;
  // A small error (5 mm along +u): offset 0.5 mm, turned a quarter to +v.
  law.setGoal(contactGoal(here.x() + 0.005, here.y()));
  law.startAt(Vec3(0.01, 0.02, f.params.radius));
  law.proxyFor(f.x);
  const Vec2 offset = law.motion().centre - Vec2(0.01, 0.02);
  EXPECT_NEAR(offset.x(), 0.0, 1e-12);
  EXPECT_NEAR(offset.y(), 0.0005, 1e-12);
  // A large one (5 cm): the offset stops at steerLimit.
  law.setGoal(contactGoal(here.x() + 0.05, here.y()));
  law.proxyFor(f.x);
  EXPECT_NEAR((law.motion().centre - Vec2(0.01, 0.02)).norm(), p.steerLimit, 1e-12);
}

TEST(HelixPolicy, LandingFadesTheCircleAtLandRateThenSettlesAtTheGlideSpeed) {
  Fixture f;
  HelixParams p;
  HelixPolicy law(f.constants, p, kDt);
  const Vec2 here = uprightContact(f.constants, f.x).point;
  law.setGoal(contactGoal(here.x(), here.y()));
  law.startAt(Vec3(0.01, 0.02, f.params.radius));
  for (int k = 0; k < 1100; ++k) law.proxyFor(f.x);
  law.land(p.landRate);
  law.proxyFor(f.x);
  EXPECT_EQ(law.phase(), HelixPhase::Land);
  EXPECT_NEAR(law.motion().radius, p.amplitude - p.landRate * kDt, 1e-15);
  // amplitude / landRate = 1 s to fade out; then it settles.
  int ticks = 1;
  while (law.phase() == HelixPhase::Land && ticks < 5000) {
    law.proxyFor(f.x);
    ++ticks;
  }
  EXPECT_EQ(law.phase(), HelixPhase::Settle);
  EXPECT_NEAR(ticks * kDt, p.amplitude / p.landRate, 2 * kDt);
  // Settling, no tick moves the proxy further than glideSpeed x dt.
  Vec3 last = law.proxyFor(f.x);
  for (int k = 0; k < 500; ++k) {
    const Vec3 proxy = law.proxyFor(f.x);
    EXPECT_LE((proxy - last).norm(), p.glideSpeed * kDt * (1.0 + 1e-12));
    last = proxy;
  }
}

TEST(HelixPolicy, TheBrakeCirclesTheContactUnsteeredThenStopsDead) {
  Fixture f;
  HelixParams p;
  HelixPolicy law(f.constants, p, kDt);
  const Vec2 here = uprightContact(f.constants, f.x).point;
  law.setGoal(contactGoal(here.x() + 0.05, here.y()));  // an error the travel would steer by
  law.startAt(Vec3(0.01, 0.02, f.params.radius));
  law.brake(0.002, -M_PI, 2.0);
  Vec3 proxy;
  for (int k = 0; k < 1500; ++k) proxy = law.proxyFor(f.x);  // the radius grows at 2 mm/s: full by 1 s
  EXPECT_TRUE(law.braking());
  EXPECT_EQ(law.phase(), HelixPhase::Travel);
  const Vec2 centre(0.01, 0.02);  // the contact: no steering offset
  EXPECT_NEAR((law.motion().centre - centre).norm(), 0.0, 1e-15);
  EXPECT_NEAR((proxy.head<2>() - centre).norm(), 0.002, 1e-12);
  const Vec3 next = law.proxyFor(f.x);
  const double a0 = std::atan2(proxy.y() - centre.y(), proxy.x() - centre.x());
  const double a1 = std::atan2(next.y() - centre.y(), next.x() - centre.x());
  EXPECT_NEAR(std::remainder(a1 - a0, 2.0 * M_PI), -M_PI * kDt, 1e-9);  // clockwise, as asked
  // After its 2 s it stops dead: settling, where the circle was.
  for (int k = 1501; k < 2010; ++k) proxy = law.proxyFor(f.x);
  EXPECT_FALSE(law.braking());
  EXPECT_EQ(law.phase(), HelixPhase::Settle);
  EXPECT_LE((law.proxyFor(f.x) - proxy).norm(), p.glideSpeed * kDt * (1.0 + 1e-12));
}

TEST(HelixPolicy, ACopyContinuesBitForBit) {
  Fixture f;
  HelixPolicy law(f.constants, HelixParams{}, kDt);
  law.setGoal(contactGoal(-0.04, -0.04));
  law.startAt(Vec3(0.01, 0.02, f.params.radius));
  for (int k = 0; k < 300; ++k) law.proxyFor(f.x);
  HelixPolicy copy = law;
  for (int k = 0; k < 300; ++k) {
    const Vec3 a = law.proxyFor(f.x), b = copy.proxyFor(f.x);
    ASSERT_EQ(a.x(), b.x());
    ASSERT_EQ(a.y(), b.y());
    ASSERT_EQ(a.z(), b.z());
  }
}

}  // namespace
}  // namespace hemiroll::autopilot
