// engine/physics/Verner98: Verner's 9(8) table against every Runge-Kutta
// order condition up to the 9th (486 rooted trees; the embedded weights
// against the 200 up to the 8th), generated from the trees
// (support/OrderConditions.h), then the pair on a known solution beside
// DOP853.

#include "engine/physics/Verner98.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/physics/support/BesideDop853.h"
#include "tests/physics/support/OrderConditions.h"

namespace hemiroll::test {
namespace {

using namespace physics;
constexpr int S = 16;

ButcherTableau<S> tableau() {
  using T = Vern9Tableau;
  ButcherTableau<S> t;
  for (int i = 0; i < S; ++i) {
    t.c[i] = T::c[i];
    t.b[i] = T::b[i];
    t.bHat[i] = T::bHat[i];
    for (int j = 0; j < S; ++j) t.a[i][j] = T::a[i][j];
  }
  return t;
}

TEST(Verner98, TheTableMeetsEveryOrderCondition) {
  const ButcherTableau<S> t = tableau();
  const auto trees = treesUpTo(t, 9);
  ASSERT_EQ(trees.size(), 486u);  // 1, 1, 2, 4, 9, 20, 48, 115, 286 trees of orders 1..9
  // Coefficients of up to 36 in size, each rounded to double once: the
  // conditions hold to a few units in the last place of the largest products.
  constexpr double kRounding = 1e-13;
  for (int i = 1; i < S; ++i) {
    double row = 0.0;
    for (int j = 0; j < i; ++j) row += t.a[i][j];
    EXPECT_NEAR(row, t.c[i], kRounding) << "row " << i << " sums to c";
  }
  const double worstB = worstResidual(trees, t.b, 1, 9), worstBHat = worstResidual(trees, t.bHat, 1, 8),
               worstBHatNinth = worstResidual(trees, t.bHat, 9, 9);
  std::printf("[measured] worst residual: b to order 9 %.1e, b_hat to order 8 %.1e, b_hat at order 9 %.1e\n", worstB,
              worstBHat, worstBHatNinth);
  EXPECT_LT(worstB, kRounding);
  EXPECT_LT(worstBHat, kRounding);
  EXPECT_GT(worstBHatNinth, 1e-8);  // the embedded solution is of order 8, not 9: an error estimate
}

TEST(Verner98, ItsErrorFollowsTheTolerance) { expectErrorFollowsToleranceBesideDop853<Verner98<2>>(); }

}  // namespace
}  // namespace hemiroll::test
