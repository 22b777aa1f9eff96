#pragma once
// A higher-order pair on the known solution at tolerances 1e-4 to 1e-12,
// beside DOP853 at the same tolerances (printed, for the reader): its error
// stays within 100 tol and falls with the tolerance. The pairs' own tests
// share it (Verner76Test, Verner98Test).

#include <gtest/gtest.h>

#include <cstdio>

#include "engine/physics/DormandPrince853.h"
#include "tests/physics/support/KnownSolution.h"

namespace hemiroll::test {

template <class Pair>
void expectErrorFollowsToleranceBesideDop853() {
  using namespace physics;
  const KnownSolutionSystem f;
  const double T = 3.0;
  double previous = 1.0;
  for (double tol = 1e-4; tol >= 1e-12; tol *= 0.01) {
    Pair m;
    m.setTolerance(tol);
    double t = 0.0;
    StateVector<2> x = KnownSolutionSystem::exact(0.0);
    ASSERT_TRUE(m.advanceTo(f, t, x, T));
    const double e = (x - KnownSolutionSystem::exact(T)).cwiseAbs().maxCoeff();
    DormandPrince853<2> d;
    d.setTolerance(tol);
    double td = 0.0;
    StateVector<2> xd = KnownSolutionSystem::exact(0.0);
    ASSERT_TRUE(d.advanceTo(f, td, xd, T));
    std::printf("[measured] tol %.0e: %s error %.2e in %lld evaluations, dop853 %.2e in %lld\n", tol,
                m.name().data(), e, m.statistics().evaluations,
                (xd - KnownSolutionSystem::exact(T)).cwiseAbs().maxCoeff(), d.statistics().evaluations);
    EXPECT_LT(e, 100.0 * tol);
    EXPECT_LT(e, previous);
    previous = e;
  }
}

}  // namespace hemiroll::test
