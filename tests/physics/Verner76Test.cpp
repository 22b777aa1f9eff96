// engine/physics/Verner76: the tableau as typed against every Runge-Kutta
// order condition up to the 7th (85 rooted trees; the embedded weights
// against the 37 up to the 6th), generated from the trees themselves
// (support/OrderConditions.h) rather than listed, then the pair on a known
// solution beside DOP853.

#include "engine/physics/Verner76.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tests/physics/support/BesideDop853.h"
#include "tests/physics/support/OrderConditions.h"

namespace hemiroll::test {
namespace {

using namespace physics;
constexpr int S = 10;

ButcherTableau<S> tableau() {
  using T = Vern7Tableau;
  ButcherTableau<S> t;
  t.c = {0.0, T::c2, T::c3, T::c4, T::c5, T::c6, T::c7, T::c8, 1.0, 1.0};
  t.a[1] = {T::a21};
  t.a[2] = {T::a31, T::a32};
  t.a[3] = {T::a41, 0.0, T::a43};
  t.a[4] = {T::a51, 0.0, T::a53, T::a54};
  t.a[5] = {T::a61, 0.0, T::a63, T::a64, T::a65};
  t.a[6] = {T::a71, 0.0, T::a73, T::a74, T::a75, T::a76};
  t.a[7] = {T::a81, 0.0, T::a83, T::a84, T::a85, T::a86, T::a87};
  t.a[8] = {T::a91, 0.0, T::a93, T::a94, T::a95, T::a96, T::a97, T::a98};
  t.a[9] = {T::a101, 0.0, T::a103, T::a104, T::a105, T::a106, T::a107};
  t.b = {T::b1, 0.0, 0.0, T::b4, T::b5, T::b6, T::b7, T::b8, T::b9, 0.0};
  t.bHat = {T::bHat1, 0.0, 0.0, T::bHat4, T::bHat5, T::bHat6, T::bHat7, 0.0, 0.0, T::bHat10};
  return t;
}

TEST(Verner76, TheTreesAreTheRightCount) {
  // 1, 1, 2, 4, 9, 20, 48 rooted trees of orders 1..7 (OEIS A000081).
  const auto trees = treesUpTo(tableau(), 7);
  int count[8] = {};
  for (const auto& t : trees) ++count[t.order];
  EXPECT_EQ(count[1], 1);
  EXPECT_EQ(count[4], 4);
  EXPECT_EQ(count[5], 9);
  EXPECT_EQ(count[6], 20);
  EXPECT_EQ(count[7], 48);
  EXPECT_EQ(trees.size(), 85u);
}

TEST(Verner76, TheTypedTableauMeetsEveryOrderCondition) {
  const ButcherTableau<S> t = tableau();
  // 17 significant digits of coefficients up to 187 in size: the conditions
  // hold to a few units in the last place of the largest products.
  constexpr double kTypedDigits = 1e-13;
  for (int i = 1; i < S; ++i) {
    double row = 0.0;
    for (int j = 0; j < i; ++j) row += t.a[i][j];
    EXPECT_NEAR(row, t.c[i], kTypedDigits) << "row " << i << " sums to c";
  }
  const auto trees = treesUpTo(t, 7);
  const double worstB = worstResidual(trees, t.b, 1, 7), worstBHat = worstResidual(trees, t.bHat, 1, 6),
               worstBHatSeventh = worstResidual(trees, t.bHat, 7, 7);
  std::printf("[measured] worst residual: b to order 7 %.1e, b_hat to order 6 %.1e, b_hat at order 7 %.1e\n", worstB,
              worstBHat, worstBHatSeventh);
  EXPECT_LT(worstB, kTypedDigits);
  EXPECT_LT(worstBHat, kTypedDigits);
  EXPECT_GT(worstBHatSeventh, 1e-6);  // the embedded solution is of order 6, not 7: an error estimate
}

// On a smooth problem at tight tolerances a 7(6) pair needs fewer
// evaluations than DOP853 for the same accuracy only sometimes; what is
// checked is that it converges with the tolerance and that the tolerance
// bounds its error.
TEST(Verner76, ItsErrorFollowsTheTolerance) { expectErrorFollowsToleranceBesideDop853<Verner76<2>>(); }

}  // namespace
}  // namespace hemiroll::test
