// engine/physics/Verner76: the tableau as typed against every Runge-Kutta
// order condition up to the 7th (85 rooted trees; the embedded weights
// against the 37 up to the 6th), generated here from the trees themselves
// rather than listed, then the pair against DOP853 on a known solution.

#include "engine/physics/Verner76.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/physics/DormandPrince853.h"
#include "tests/physics/support/KnownSolution.h"

namespace hemiroll::test {
namespace {

using namespace physics;
constexpr int S = 10;
using Vec = std::array<double, S>;

struct Tableau {
  std::array<Vec, S> a{};
  Vec b{}, bHat{}, c{};
};

Tableau tableau() {
  using T = Vern7Tableau;
  Tableau t;
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

// A rooted tree by what the conditions need: its order, its density gamma
// and its elementary weights Phi_i (the product over the root's subtrees u of
// (A Phi(u))_i; all ones for the single node). b . Phi = 1 / gamma.
struct Tree {
  int order = 1;
  double gamma = 1.0;
  Vec phi{};
};

// Every rooted tree up to `maxOrder`, each once: a tree is its root's
// multiset of subtrees, built as a non-increasing list of indices into the
// trees already made, so that no two lists name the same tree.
std::vector<Tree> treesUpTo(const Tableau& t, int maxOrder) {
  std::vector<Tree> trees;
  Tree node;
  node.phi.fill(1.0);
  trees.push_back(node);
  std::vector<Vec> aPhi;  // A Phi(u) of each tree u made so far
  const auto times = [&](const Vec& phi) {
    Vec out{};
    for (int i = 0; i < S; ++i)
      for (int j = 0; j < S; ++j) out[i] += t.a[i][j] * phi[j];
    return out;
  };
  aPhi.push_back(times(node.phi));
  for (int order = 2; order <= maxOrder; ++order) {
    const std::size_t known = trees.size();  // subtrees have order < `order`
    std::vector<Tree> made;
    // children: non-increasing indices into trees[0, known); their orders sum to order - 1.
    std::vector<std::size_t> children;
    const auto extend = [&](auto&& self, std::size_t maxIndex, int remaining) -> void {
      if (remaining == 0) {
        Tree tree;
        tree.order = order;
        tree.phi.fill(1.0);
        double gamma = order;
        for (const std::size_t c : children) {
          gamma *= trees[c].gamma;
          for (int i = 0; i < S; ++i) tree.phi[i] *= aPhi[c][i];
        }
        tree.gamma = gamma;
        made.push_back(tree);
        return;
      }
      for (std::size_t c = 0; c <= maxIndex && c < known; ++c) {
        if (trees[c].order > remaining) continue;
        children.push_back(c);
        self(self, c, remaining - trees[c].order);
        children.pop_back();
      }
    };
    extend(extend, known - 1, order - 1);
    for (const Tree& tree : made) {
      trees.push_back(tree);
      aPhi.push_back(times(tree.phi));
    }
  }
  return trees;
}

double residual(const Vec& b, const Tree& tree) {
  double s = 0.0;
  for (int i = 0; i < S; ++i) s += b[i] * tree.phi[i];
  return s - 1.0 / tree.gamma;
}

TEST(Verner76, TheTreesAreTheRightCount) {
  // 1, 1, 2, 4, 9, 20, 48 rooted trees of orders 1..7 (OEIS A000081).
  const std::vector<Tree> trees = treesUpTo(tableau(), 7);
  int count[8] = {};
  for (const Tree& t : trees) ++count[t.order];
  EXPECT_EQ(count[1], 1);
  EXPECT_EQ(count[4], 4);
  EXPECT_EQ(count[5], 9);
  EXPECT_EQ(count[6], 20);
  EXPECT_EQ(count[7], 48);
  EXPECT_EQ(trees.size(), 85u);
}

TEST(Verner76, TheTypedTableauMeetsEveryOrderCondition) {
  const Tableau t = tableau();
  // 17 significant digits of coefficients up to 187 in size: the conditions
  // hold to a few units in the last place of the largest products.
  constexpr double kTypedDigits = 1e-13;
  for (int i = 1; i < S; ++i) {
    double row = 0.0;
    for (int j = 0; j < i; ++j) row += t.a[i][j];
    EXPECT_NEAR(row, t.c[i], kTypedDigits) << "row " << i << " sums to c";
  }
  double worstB = 0.0, worstBHat = 0.0, worstBHatSeventh = 0.0;
  for (const Tree& tree : treesUpTo(t, 7)) {
    worstB = std::max(worstB, std::abs(residual(t.b, tree)));
    if (tree.order <= 6) worstBHat = std::max(worstBHat, std::abs(residual(t.bHat, tree)));
    else worstBHatSeventh = std::max(worstBHatSeventh, std::abs(residual(t.bHat, tree)));
  }
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
TEST(Verner76, ItsErrorFollowsTheTolerance) {
  const KnownSolutionSystem f;
  const double T = 3.0;
  double previous = 1.0;
  for (double tol = 1e-4; tol >= 1e-12; tol *= 0.01) {
    Verner76<2> m;
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
    std::printf("[measured] tol %.0e: vern7 error %.2e in %lld evaluations, dop853 %.2e in %lld\n", tol, e,
                m.statistics().evaluations, (xd - KnownSolutionSystem::exact(T)).cwiseAbs().maxCoeff(),
                d.statistics().evaluations);
    EXPECT_LT(e, 100.0 * tol);
    EXPECT_LT(e, previous);
    previous = e;
  }
}

}  // namespace
}  // namespace hemiroll::test
