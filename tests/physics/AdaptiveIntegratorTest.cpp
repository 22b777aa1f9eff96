// AdaptiveIntegrator.h with the three pairs: the error at the end tracks the
// tolerance, the dense output has the continuous extension's order, and the
// Integrator<N>::step interface lands exactly on t + h.

#include <gtest/gtest.h>

#include <cstdio>

#include "engine/physics/Physics.h"
#include "tests/physics/support/ConvergenceOrder.h"
#include "tests/physics/support/KnownSolution.h"

namespace hemiroll::test {
namespace {

using namespace physics;

template <class M>
void expectErrorTracksTolerance() {
  const double T = 3.0;
  std::vector<double> tols, errors;
  for (double tol = 1e-4; tol >= 1e-10; tol *= 0.01) {
    const KnownSolutionRun run = runKnownSolution<M>(tol, T);
    ASSERT_TRUE(run.reached);
    EXPECT_EQ(run.t, T);
    const double e = run.error;
    std::printf("[measured] %s tol %.0e: error %.2e (%lld evaluations)\n", M().name().data(), tol, e, run.evaluations);
    // The tolerance bounds the local error per step, so the global error over
    // 3 s (of order 1 solution, ~3 time units) is within ~10x of tol for a
    // well-behaved problem; 30x leaves room for error accumulation. Far below
    // tol (1e-3 x) would mean the control wastes work.
    EXPECT_LT(e, 30.0 * tol);
    EXPECT_GT(e, 1e-3 * tol);
    tols.push_back(tol);
    errors.push_back(e);
  }
  // Proportionality: the slope of log(error) against log(tol) is ~1 for a
  // controlled error per step (Hairer's "tolerance proportionality",
  // p/(p+1) in theory for error-per-step control: 0.83 for 5(4), 0.89 for 8).
  const double slope = observedOrder(tols, errors);
  std::printf("[measured] %s: d log(error) / d log(tol) = %.2f\n", M().name().data(), slope);
  EXPECT_GT(slope, 0.7);
  EXPECT_LT(slope, 1.2);
}

TEST(AdaptiveIntegrator, Dopri5ErrorTracksTolerance) { expectErrorTracksTolerance<DormandPrince54<2>>(); }
TEST(AdaptiveIntegrator, Dop853ErrorTracksTolerance) { expectErrorTracksTolerance<DormandPrince853<2>>(); }
TEST(AdaptiveIntegrator, Tsit5ErrorTracksTolerance) { expectErrorTracksTolerance<Tsitouras54<2>>(); }
TEST(AdaptiveIntegrator, Vern7ErrorTracksTolerance) { expectErrorTracksTolerance<Verner76<2>>(); }

// Dense output: with equal steps, the largest interpolation error at the
// quarter points of every step, against the closed form. The continuous
// extensions have orders 4 (DOPRI5) and 7 (DOP853), local error h^5 and h^8,
// and the global error of the step ends is h^5 and h^8: the observed order
// must be 5 and 8 (band as in IntegratorOrderTest).
template <class M>
double denseOrder(int n0, int halvings) {
  const KnownSolutionSystem f;
  const double T = 3.0;
  std::vector<double> steps, errors;
  for (int k = 0, n = n0; k <= halvings; ++k, n *= 2) {
    M m;
    const double h = T / n;
    m.start(f, 0.0, KnownSolutionSystem::exact(0.0));
    double worst = 0.0;
    for (int i = 0; i < n; ++i) {
      m.takeFixedStep(f, h);
      for (double theta : {0.25, 0.5, 0.75}) {
        const double t = (i + theta) * h;
        StateVector<2> x;
        m.interpolate(t, x);
        worst = std::max(worst, (x - KnownSolutionSystem::exact(t)).cwiseAbs().maxCoeff());
      }
    }
    steps.push_back(h);
    errors.push_back(worst);
  }
  const double p = observedOrder(steps, errors);
  std::printf("[measured] %s dense output: order %.2f (errors %.1e .. %.1e)\n", M().name().data(), p, errors.front(),
              errors.back());
  return p;
}

TEST(AdaptiveIntegrator, Dopri5DenseOutputIsFifthOrderAccurate) {
  const double p = denseOrder<DormandPrince54<2>>(30, 2);
  EXPECT_GE(p, 4.7);
  EXPECT_LE(p, 5.6);
}

// Tsit5's, Vern7's and Vern9's dense output is ExplicitPair's cubic Hermite
// (Verner's own interpolants need more stages): local error h^4, order 4.
TEST(AdaptiveIntegrator, TheCubicHermiteDenseOutputsAreFourthOrder) {
  for (const double p : {denseOrder<Tsitouras54<2>>(30, 2), denseOrder<Verner76<2>>(30, 2),
                         denseOrder<Verner98<2>>(30, 2)}) {
    EXPECT_GE(p, 3.7);
    EXPECT_LE(p, 4.6);
  }
}

TEST(AdaptiveIntegrator, Dop853DenseOutputIsEighthOrderAccurate) {
  const double p = denseOrder<DormandPrince853<2>>(4, 2);
  EXPECT_GE(p, 7.7);
  EXPECT_LE(p, 8.6);
}

TEST(AdaptiveIntegrator, DenseOutputMatchesStepEnds) {
  // At theta = 0 and 1 the interpolant must return the step's end points.
  const KnownSolutionSystem f;
  DormandPrince853<2> m;
  m.start(f, 0.0, KnownSolutionSystem::exact(0.0));
  ASSERT_TRUE(m.takeStep(f, 10.0));
  StateVector<2> x;
  m.interpolate(m.time(), x);
  EXPECT_LT((x - m.state()).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(AdaptiveIntegrator, StepInterfaceEndsExactlyAtTPlusH) {
  const KnownSolutionSystem f;
  DormandPrince54<2> m;
  m.setTolerance(1e-10);
  StateVector<2> x = KnownSolutionSystem::exact(0.0);
  for (int i = 0; i < 30; ++i) m.step(f, 0.1 * i, x, 0.1);
  EXPECT_NEAR(m.time(), 3.0, 1e-14);
  EXPECT_LT((x - KnownSolutionSystem::exact(3.0)).cwiseAbs().maxCoeff(), 1e-8);
}

}  // namespace
}  // namespace hemiroll::test
