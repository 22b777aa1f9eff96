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
  double previous = 1.0;
  for (double tol = 1e-4; tol >= 1e-12; tol *= 0.01) {
    const KnownSolutionRun run = runKnownSolution<Pair>(tol), dop853 = runKnownSolution<physics::DormandPrince853<2>>(tol);
    ASSERT_TRUE(run.reached && dop853.reached);
    std::printf("[measured] tol %.0e: %s error %.2e in %lld evaluations, dop853 %.2e in %lld\n", tol,
                Pair().name().data(), run.error, run.evaluations, dop853.error, dop853.evaluations);
    EXPECT_LT(run.error, 100.0 * tol);
    EXPECT_LT(run.error, previous);
    previous = run.error;
  }
}

}  // namespace hemiroll::test
