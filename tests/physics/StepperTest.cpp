// Stepper.h: domain events located at the right time and leaving a valid
// state, robustness at the rim, and bit-for-bit determinism.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/Stepper.h"
#include "tests/physics/support/Drives.h"
#include "tests/physics/support/Integration.h"

namespace hemiroll::test {
namespace {

using physics::DomainEvent;
using physics::ForceDrivenSystem;
using physics::ForceDrivenState;
using physics::Stepper;

bool inside(const physics::DomainMargins& m) { return m.tilt >= 0.0 && m.face >= 0.0; }

// Independent event time: RK4 at a fine step until the state leaves the
// domain, then bisection on the length of one RK4 step from the last inside
// state, down to 1e-14 s.
double referenceEventTime(const ForceDrivenSystem& sys, ForceDrivenState x, double h) {
  physics::RungeKutta4<12> rk4;
  double t = 0.0;
  for (;;) {
    ForceDrivenState next = x;
    rk4.step(sys, t, next, h);
    if (!inside(sys.margins(t + h, next))) break;
    x = next;
    t += h;
  }
  double lo = 0.0, hi = h;
  while (hi - lo > 1e-14) {
    const double mid = 0.5 * (lo + hi);
    ForceDrivenState probe = x;
    rk4.step(sys, t, probe, mid);
    (inside(sys.margins(t + mid, probe)) ? lo : hi) = mid;
  }
  return t + lo;
}

struct EventRun {
  DomainEvent event;
  double time;
  ForceDrivenState state;
};

EventRun runUntilEvent(const ForceDrivenSystem& sys, const ForceDrivenState& x0, double h) {
  physics::RungeKutta4<12> rk4;
  Stepper<12> stepper(sys, rk4, x0);
  for (int i = 0; i < 100000 && !stepper.halted(); ++i) stepper.advance(h);
  const EventRun run{stepper.event(), stepper.time(), stepper.state()};
  // Once halted, advancing does nothing.
  const physics::StepReport again = stepper.advance(h);
  EXPECT_EQ(again.event, run.event);
  EXPECT_EQ(again.time, run.time);
  EXPECT_EQ(stepper.state(), run.state);
  return run;
}

// The stepper integrates at 0.1 ms; the reference at 1 us. Both are RK4, so
// their trajectories differ by ~(1e-4 w)^4 relative ~ 1e-11 over these 0.1 s
// runs (w ~ 100 rad/s near the rim), and the event times by that over the
// margin's rate of change: ~1e-11 s. The stepper's own bisection stops at
// kEventTimeTolerance = 1e-10 s. 1e-9 s bounds both with margin.
constexpr double kStep = 1e-4;
constexpr double kReferenceStep = 1e-6;
constexpr double kEventTimeTolerance = 1e-9;

void expectEventAt(const ForceDrivenSystem& sys, const ForceDrivenState& x0, DomainEvent expected, const char* what) {
  const EventRun run = runUntilEvent(sys, x0, kStep);
  const double reference = referenceEventTime(sys, x0, kReferenceStep);
  std::printf("[measured] %s: event at %.12f s, reference %.12f s, |dt| = %.1e s\n", what, run.time, reference,
              std::abs(run.time - reference));
  EXPECT_EQ(run.event, expected) << physics::domainEventName(run.event);
  EXPECT_NEAR(run.time, reference, kEventTimeTolerance);
  EXPECT_TRUE(run.state.allFinite());
  EXPECT_TRUE(inside(sys.margins(run.time, run.state)));
  // The state is at the edge, not short of it: the margin left is what the
  // bisection's 1e-10 s can leave at the margin's rate (< 1e-6 here).
  const physics::DomainMargins m = sys.margins(run.time, run.state);
  EXPECT_LT(expected == DomainEvent::TippedOver ? m.tilt : m.face, 1e-6);
}

TEST(Stepper, FastRockingTowardTheRimTipsOver) {
  const HemisphereParams par = paperParams();
  ForceDrivenSystem sys(par);
  ForceDrivenState x0 = ForceDrivenState::Zero();
  x0(5) = -10.0;  // w_y < 0 at psi = v_o = 0 drives u_o up (eq. 13)
  x0(9) = 1.0;    // 57 deg already
  expectEventAt(sys, x0, DomainEvent::TippedOver, "tip-over");
}

TEST(Stepper, OutwardFaceForceDrivesThePointOffTheFace) {
  const HemisphereParams par = paperParams();
  ForceDrivenSystem sys(par);
  sys.setFaceForce(Vec2(0.0, 4.0));
  expectEventAt(sys, ForceDrivenState::Zero(), DomainEvent::LeftFace, "off-face");
}

TEST(Stepper, NearTheRimNeverProducesNonFiniteStates) {
  const HemisphereParams par = paperParams();
  ForceDrivenSystem sys(par);
  std::mt19937_64 rng(8589);
  int events[4] = {0, 0, 0, 0};
  int nonFinite = 0, outside = 0;
  for (int i = 0; i < 2000; ++i) {
    RandomStateSpec spec;
    spec.maxSpin = 40.0;
    State12 x = randomState(rng, par, spec);
    // Tilt in 85..89.99 deg along a random azimuth: cos u cos v = cos(tilt).
    const double tilt = uniform(rng, 85.0, 89.99) * kDeg, azimuth = uniform(rng, -kPi, kPi);
    const Vec3 k(std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), std::cos(tilt));
    // Row 3 of R is (sin u cos v, -sin v, cos u cos v): any unit vector with a
    // positive last entry is reached by u = atan2(k_x, k_z), v = -asin(k_y).
    x(9) = std::atan2(k.x(), k.z());
    x(10) = -std::asin(k.y());
    physics::RungeKutta4<12> rk4;
    Stepper<12> stepper(sys, rk4, x);
    for (int s = 0; s < 100; ++s) {
      stepper.advance(1e-3);
      if (!stepper.state().allFinite()) ++nonFinite;
    }
    ++events[static_cast<int>(stepper.event())];
    if (!inside(sys.margins(stepper.time(), stepper.state()))) ++outside;
  }
  std::printf("[measured] near rim, 2000 states x 100 steps: none %d, tipped %d, left face %d, non-finite event %d\n",
              events[0], events[1], events[2], events[3]);
  EXPECT_EQ(nonFinite, 0);
  EXPECT_EQ(outside, 0);
}

// Determinism in the manner of Box2D's test: hash the bits of the state after
// a fixed run; two runs must hash alike. A perturbation of one ulp in the
// start must change the hash, or the hash would prove nothing.
std::uint64_t hashBits(const ForceDrivenState& x, std::uint64_t h = 1469598103934665603ull) {
  for (int i = 0; i < x.size(); ++i) {
    std::uint64_t bits;
    const double v = x(i);
    std::memcpy(&bits, &v, sizeof bits);
    for (int b = 0; b < 8; ++b) {
      h ^= (bits >> (8 * b)) & 0xffu;
      h *= 1099511628211ull;  // FNV-1a
    }
  }
  return h;
}

std::uint64_t coupledRunHash(double startNudge) {
  const HemisphereParams par = paperParams();
  const CirclingProxy proxy;
  ForceDrivenSystem sys(par);
  sys.setCoupling(physics::CouplingDef{physics::ForceMethod::M3, 250.0, 10.0, 2.0, false}, proxy);
  ForceDrivenState x0 = ForceDrivenState::Zero();
  x0(0) = 0.003 + startNudge;
  physics::RungeKutta4<12> rk4;
  Stepper<12> stepper(sys, rk4, x0);
  std::uint64_t h = 1469598103934665603ull;
  for (int i = 0; i < 2000; ++i) {
    stepper.advance(1e-3);
    if (i % 100 == 99) h = hashBits(stepper.state(), h);
  }
  return h;
}

TEST(Stepper, RunsAreBitForBitDeterministic) {
  const std::uint64_t first = coupledRunHash(0.0), second = coupledRunHash(0.0);
  const std::uint64_t nudged = coupledRunHash(std::nextafter(0.003, 1.0) - 0.003);
  std::printf("[measured] hash %016llx, again %016llx, nudged start %016llx\n",
              static_cast<unsigned long long>(first), static_cast<unsigned long long>(second),
              static_cast<unsigned long long>(nudged));
  EXPECT_EQ(first, second);
  EXPECT_NE(first, nudged);
}

}  // namespace
}  // namespace hemiroll::test
