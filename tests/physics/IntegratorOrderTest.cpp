// Orders of convergence of every integrator (DormandPrince54.h,
// DormandPrince853.h, GaussLegendre.h, Integrator.h's RK4), measured as the
// least-squares slope of log(error) against log(h) over step halvings:
//  - on KnownSolution.h's problem, against its closed form;
//  - on the free rolling model (0.35 s, inside the domain, from a tilted, spinning start), against
//    dop853ld at tol 1e-15 (error ~1e-14, below every error used here).
// Adaptive pairs are run with equal steps (takeFixedStep) so that the order of
// the propagated solution is what is measured.
//
// Bands: [p - 0.3, p + 0.6]. Step ranges are chosen so that errors stay 100x
// above round-off (1e-16 relative) and below 1e-3 (asymptotic regime); the
// next error term O(h^{p+1}) still tilts the slope upward at the coarse end,
// hence the asymmetric band. A one-order mistake (a wrong coefficient breaks
// an order condition) moves the slope by >= 1 and fails.

#include <gtest/gtest.h>

#include <cstdio>

#include "engine/physics/Physics.h"
#include "tests/physics/support/ConvergenceOrder.h"
#include "tests/physics/support/KnownSolution.h"

namespace hemiroll::test {
namespace {

using namespace physics;

template <class M>
double knownOrder(int n0, int halvings) {
  const KnownSolutionSystem f;
  const double T = 3.0;
  std::vector<double> e;
  const double p = measuredOrder<M, 2>(f, KnownSolutionSystem::exact(0.0), T, KnownSolutionSystem::exact(T), n0,
                                       halvings, &e);
  std::printf("[measured] known solution, %s: order %.2f (errors %.1e .. %.1e)\n", M().name().data(), p, e.front(),
              e.back());
  return p;
}

struct FreeModel {
  ForceDrivenSystem system{HemisphereParams{}};
  ForceDrivenState x0;
  ForceDrivenState reference;
  static constexpr double T = 0.35;  // the point reaches the face edge at 0.3557 s
  FreeModel() {
    x0 << 0.002, -0.001, 0.0, 0.004, 0.2, -0.1, 4.0, 0.0, 0.0, 0.08, -0.05, 0.3;
    DormandPrince853LongDouble<12> ref;
    ref.setTolerance(1e-15);
    double t = 0.0;
    reference = x0;
    ref.advanceTo(system, t, reference, T);
  }
};

template <class M>
double freeOrder(int n0, int halvings) {
  static const FreeModel model;
  std::vector<double> e;
  const double p = measuredOrder<M, 12>(model.system, model.x0, FreeModel::T, model.reference, n0, halvings, &e);
  std::printf("[measured] free rolling, %s: order %.2f (errors %.1e .. %.1e)\n", M().name().data(), p, e.front(),
              e.back());
  return p;
}

void expectOrder(double measured, int p) {
  EXPECT_GE(measured, p - 0.3);
  EXPECT_LE(measured, p + 0.6);
}

TEST(IntegratorOrder, RungeKutta4IsFourthOrder) {
  expectOrder(knownOrder<RungeKutta4<2>>(15, 3), 4);
  expectOrder(freeOrder<RungeKutta4<12>>(400, 3), 4);
}

TEST(IntegratorOrder, GaussLegendre2IsFourthOrder) {
  expectOrder(knownOrder<GaussLegendre2<2>>(15, 3), 4);
  expectOrder(freeOrder<GaussLegendre2<12>>(400, 3), 4);
}

TEST(IntegratorOrder, GaussLegendre3IsSixthOrder) {
  expectOrder(knownOrder<GaussLegendre3<2>>(15, 2), 6);
  expectOrder(freeOrder<GaussLegendre3<12>>(400, 2), 6);
}

TEST(IntegratorOrder, DormandPrince54IsFifthOrder) {
  expectOrder(knownOrder<DormandPrince54<2>>(30, 2), 5);
  expectOrder(freeOrder<DormandPrince54<12>>(200, 3), 5);
}

TEST(IntegratorOrder, DormandPrince853IsEighthOrder) {
  // DOP853 reaches round-off within two halvings of h = 0.75 s, so its
  // asymptotic range is narrow and the coarse end superconverges (measured
  // 9.3): band [p - 0.3, p + 2] here and below; an order-5 defect still fails.
  const double known = knownOrder<DormandPrince853<2>>(4, 2);
  EXPECT_GE(known, 7.7);
  EXPECT_LE(known, 10.0);
  // The rolling model's error constant is pre-asymptotic at the coarse end
  // (one halving shows 11): measured ~8.8 over three halvings, inside a band
  // widened to p + 2 for this case only; an order-5 defect still fails.
  const double p = freeOrder<DormandPrince853<12>>(50, 3);
  EXPECT_GE(p, 7.7);
  EXPECT_LE(p, 10.0);
}

}  // namespace
}  // namespace hemiroll::test
