// DomainEvents.h: the trigonometry-free InteriorCheck, and the models'
// domainEvent() built on it, must answer exactly as the exact margins do
// (the stepper's event location by bisection depends on it), above all on
// states right at the edges.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/physics/DomainEvents.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/PrescribedDriveSystem.h"
#include "tests/physics/support/Drives.h"
#include "tests/physics/support/TestModel.h"

namespace hemiroll::test {
namespace {

using physics::DomainEvent;
using physics::DomainLimits;
using physics::DomainMargins;
using physics::InteriorCheck;

DomainEvent exactEvent(const DomainMargins& m, bool finite) { return physics::classifyDomain(m, finite); }

// Limits from the rim down to a nearly upright cone, and smaller faces.
const DomainLimits kLimits[] = {{}, {1.2, 1.0}, {0.3, 0.5}, {1e-3, 1.0}, {kPi / 2, 1e-3}};

TEST(InteriorCheck, PassesOnlyStatesWhoseExactMarginsAreInside) {
  // Where the test is tightest: on an axis (cos u cos v = cos(|u| + |v|)),
  // and with |p| right at the face edge; sampled finely across the point
  // where the check starts to refuse.
  std::mt19937_64 rng(11);
  int passed = 0;
  for (const DomainLimits& limits : kLimits) {
    const HemisphereParams par = paperParams();
    physics::ForceDrivenSystem system(par, limits);
    const double cosMax = std::cos(limits.maxTilt), faceLimit = limits.maxPointRadius * par.radius;
    const InteriorCheck check(cosMax, faceLimit);
    const double edge = std::acos(cosMax + 1e-9);  // where the check's room in cos runs out
    const double rim = std::acos(cosMax);          // where the exact tilt margin turns negative
    for (int i = 0; i < 300000; ++i) {
      // The check refuses from edge * (1 - 1e-9) on: straddle that finely,
      // straddle the true edge more finely still, and sweep both coarsely.
      const double angle = i % 3 == 0   ? edge * (1.0 + uniform(rng, -2e-9, 0.0))
                           : i % 3 == 1 ? rim * (1.0 + uniform(rng, -1e-12, 1e-12))
                                        : edge * (1.0 + uniform(rng, -1e-8, 1e-8));
      const double split = i % 4 == 0 ? 0.0 : uniform(rng, 0.0, 1.0);  // on the axis, or shared
      const double u = (i % 2 ? 1.0 : -1.0) * split * angle, v = (i % 3 ? 1.0 : -1.0) * (1.0 - split) * angle;
      const double r = faceLimit * (1.0 + uniform(rng, -2e-6, 1e-6));
      const double phi = uniform(rng, -kPi, kPi);
      State12 x = State12::Zero();
      x[physics::force_slot::u_o] = u;
      x[physics::force_slot::v_o] = v;
      x[physics::force_slot::x_p] = r * std::cos(phi);
      x[physics::force_slot::y_p] = r * std::sin(phi);
      if (!check.surelyInside(u, v, x[physics::force_slot::x_p], x[physics::force_slot::y_p])) continue;
      ++passed;
      const DomainMargins m = system.margins(0.0, x);
      ASSERT_GE(m.tilt, 0.0) << "u " << u << " v " << v << " maxTilt " << limits.maxTilt;
      ASSERT_GE(m.face, 0.0) << "r " << r << " limit " << faceLimit;
    }
  }
  // The samples straddle the refusal point, so some must have passed.
  EXPECT_GT(passed, 1000);
}

TEST(InteriorCheck, CoversTheStatesOfPlayAndRefusesNonFiniteInput) {
  const double R = paperParams().radius;
  const InteriorCheck check(std::cos(DomainLimits{}.maxTilt), R);
  // Tilted by up to ~70 degrees in angle sum, the mass point at 0.99 R: no
  // trigonometry needed.
  EXPECT_TRUE(check.surelyInside(0.6, -0.6, 0.99 * R, 0.0));
  EXPECT_TRUE(check.surelyInside(0.0, 0.0, 0.0, 0.0));
  EXPECT_FALSE(check.surelyInside(1.0, 0.6, 0.0, 0.0));  // 1.6 rad > pi/2: decided exactly
  EXPECT_FALSE(check.surelyInside(0.0, 0.0, R, 0.0));    // at the face edge: decided exactly
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(check.surelyInside(nan, 0.0, 0.0, 0.0));
  EXPECT_FALSE(check.surelyInside(0.0, 0.0, inf, 0.0));
  EXPECT_FALSE(check.surelyInside(0.0, 0.0, 0.0, nan));
  // Degenerate limits: nothing is surely inside.
  EXPECT_FALSE(InteriorCheck(1.0, R).surelyInside(0.0, 0.0, 0.0, 0.0));
  EXPECT_FALSE(InteriorCheck(0.0, 0.0).surelyInside(0.0, 0.0, 0.0, 0.0));
  EXPECT_FALSE(InteriorCheck(nan, nan).surelyInside(0.0, 0.0, 0.0, 0.0));
}

// Random states across both edges, with a non-finite slot now and then.
State12 edgyState(std::mt19937_64& rng, const HemisphereParams& par, int i) {
  State12 x = randomState(rng, par, RandomStateSpec{});
  using namespace physics::force_slot;
  x[u_o] = uniform(rng, -1.7, 1.7);
  x[v_o] = uniform(rng, -1.7, 1.7);
  const double r = par.radius * uniform(rng, 0.0, 1.05), phi = uniform(rng, -kPi, kPi);
  x[x_p] = r * std::cos(phi);
  x[y_p] = r * std::sin(phi);
  if (i % 97 == 0) x[i % 12] = i % 2 ? std::numeric_limits<double>::quiet_NaN() : -std::numeric_limits<double>::infinity();
  return x;
}

TEST(DomainEvent, ForceDrivenModelAnswersAsItsMargins) {
  std::mt19937_64 rng(12);
  const HemisphereParams par = paperParams();
  int counts[4] = {0, 0, 0, 0};
  for (const DomainLimits& limits : kLimits) {
    const physics::ForceDrivenSystem system(par, limits);
    for (int i = 0; i < 50000; ++i) {
      const State12 x = edgyState(rng, par, i);
      const DomainEvent fast = system.domainEvent(0.0, x);
      ASSERT_EQ(fast, exactEvent(system.margins(0.0, x), x.allFinite())) << "state " << x.transpose();
      ++counts[static_cast<int>(fast)];
    }
  }
  // Every answer occurs, so each branch was compared.
  for (int c : counts) EXPECT_GT(c, 100);
}

TEST(DomainEvent, PrescribedDriveAnswersAsItsMargins) {
  std::mt19937_64 rng(13);
  const HemisphereParams par = paperParams();
  for (const DomainLimits& limits : kLimits) {
    for (int i = 0; i < 20000; ++i) {
      const State12 x = edgyState(rng, par, i);
      const HeldPoint point(Vec2(x[0], x[1]));
      const physics::PrescribedDriveSystem system(par, point, limits);
      const State8 body = x.tail<8>();
      ASSERT_EQ(system.domainEvent(0.0, body), exactEvent(system.margins(0.0, body), body.allFinite()));
    }
  }
}

}  // namespace
}  // namespace hemiroll::test
