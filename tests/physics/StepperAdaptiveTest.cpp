// Stepper.h with adaptive integrators: events located on the dense output to
// within 1e-9 s of an independent bisection (RK4 at 1 us, then bisection on
// the length of one step to 1e-14 s; its own error ~1e-11 s, see
// StepperTest.cpp), and output-grid states that match the integrator's.

#include <gtest/gtest.h>

#include <cstdio>

#include "engine/physics/Physics.h"

namespace hemiroll::test {
namespace {

using namespace physics;

bool inside(const DomainMargins& m) { return m.tilt >= 0.0 && m.face >= 0.0; }

double referenceEventTime(const ForceDrivenSystem& sys, ForceDrivenState x, double h) {
  RungeKutta4<12> rk4;
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

// tol 1e-12: the trajectory (and so the dense output) is accurate to ~1e-11
// in the state; divided by the margins' rates (> 0.1 per s here) that is
// < 1e-10 s, and the bisection on the dense output stops at 1e-10 s.
template <class M>
void expectEventAt(const ForceDrivenSystem& sys, const ForceDrivenState& x0, DomainEvent expected) {
  M method;
  method.setTolerance(1e-12);
  Stepper<12> stepper(sys, method, x0);
  for (int i = 0; i < 10000 && !stepper.halted(); ++i) stepper.advance(1e-2);  // a coarse output grid
  const double reference = referenceEventTime(sys, x0, 1e-6);
  std::printf("[measured] %s: %s at %.12f s, reference %.12f s, |dt| = %.1e s, %lld evaluations\n",
              method.name().data(), domainEventName(stepper.event()), stepper.time(), reference,
              std::abs(stepper.time() - reference), method.statistics().evaluations);
  EXPECT_EQ(stepper.event(), expected);
  EXPECT_NEAR(stepper.time(), reference, 1e-9);
  EXPECT_TRUE(stepper.state().allFinite());
  EXPECT_TRUE(inside(sys.margins(stepper.time(), stepper.state())));
}

ForceDrivenState tipOverStart() {
  ForceDrivenState x0 = ForceDrivenState::Zero();
  x0(5) = -10.0;
  x0(9) = 1.0;
  return x0;
}

TEST(StepperAdaptive, TipOverLocatedOnDenseOutput) {
  ForceDrivenSystem sys{HemisphereParams{}};
  expectEventAt<DormandPrince54<12>>(sys, tipOverStart(), DomainEvent::TippedOver);
  expectEventAt<DormandPrince853<12>>(sys, tipOverStart(), DomainEvent::TippedOver);
}

TEST(StepperAdaptive, OffFaceLocatedOnDenseOutput) {
  ForceDrivenSystem sys{HemisphereParams{}};
  sys.setFaceForce(Vec2(0.0, 4.0));
  expectEventAt<DormandPrince54<12>>(sys, ForceDrivenState::Zero(), DomainEvent::LeftFace);
  expectEventAt<DormandPrince853<12>>(sys, ForceDrivenState::Zero(), DomainEvent::LeftFace);
}

TEST(StepperAdaptive, GridStatesAgreeWithDirectIntegration) {
  // Output every 1 ms from the dense output vs integrating straight to each
  // output time: both are tol-accurate solutions, so they agree to ~tol.
  ForceDrivenSystem sys{HemisphereParams{}};
  ForceDrivenState x0;
  x0 << 0.002, -0.001, 0.0, 0.004, 0.2, -0.1, 4.0, 0.0, 0.0, 0.08, -0.05, 0.3;
  DormandPrince853<12> a, b;
  a.setTolerance(1e-11);
  b.setTolerance(1e-11);
  Stepper<12> stepper(sys, a, x0);
  for (int i = 1; i <= 300; ++i) stepper.advanceTo(i * 1e-3);  // left_face at 0.3557 s
  double t = 0.0;
  ForceDrivenState x = x0;
  b.advanceTo(sys, t, x, 0.3);
  EXPECT_EQ(stepper.time(), 0.3);
  EXPECT_LT((stepper.state() - x).cwiseAbs().maxCoeff(), 1e-8);
}

}  // namespace
}  // namespace hemiroll::test
