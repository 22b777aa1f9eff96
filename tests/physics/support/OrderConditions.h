#pragma once
// Runge-Kutta order conditions generated from the rooted trees themselves
// (Butcher): for every tree t up to a given order, b . Phi(t) = 1 / gamma(t),
// where the elementary weights Phi_i(t) are the product over the root's
// subtrees u of (A Phi(u))_i (all ones for the single node) and the density
// gamma(t) = |t| times the product of the subtrees' densities. Used by the
// tests of the higher-order pairs, whose conditions are too many to list.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

namespace hemiroll::test {

template <int S>
struct ButcherTableau {
  std::array<std::array<double, S>, S> a{};
  std::array<double, S> b{}, bHat{}, c{};
};

template <int S>
struct RootedTree {
  int order = 1;
  double gamma = 1.0;
  std::array<double, S> phi{};
};

// Every rooted tree up to `maxOrder`, each once: a tree is its root's
// multiset of subtrees, built as a non-increasing list of indices into the
// trees already made, so that no two lists name the same tree.
template <int S>
std::vector<RootedTree<S>> treesUpTo(const ButcherTableau<S>& t, int maxOrder) {
  using Vec = std::array<double, S>;
  const auto times = [&](const Vec& phi) {
    Vec out{};
    for (int i = 0; i < S; ++i)
      for (int j = 0; j < S; ++j) out[i] += t.a[i][j] * phi[j];
    return out;
  };
  std::vector<RootedTree<S>> trees;
  RootedTree<S> node;
  node.phi.fill(1.0);
  trees.push_back(node);
  std::vector<Vec> aPhi{times(node.phi)};  // A Phi(u) of each tree u made so far
  for (int order = 2; order <= maxOrder; ++order) {
    const std::size_t known = trees.size();  // subtrees have order < `order`
    std::vector<RootedTree<S>> made;
    std::vector<std::size_t> children;
    const auto extend = [&](auto&& self, std::size_t maxIndex, int remaining) -> void {
      if (remaining == 0) {
        RootedTree<S> tree;
        tree.order = order;
        tree.phi.fill(1.0);
        tree.gamma = order;
        for (const std::size_t c : children) {
          tree.gamma *= trees[c].gamma;
          for (int i = 0; i < S; ++i) tree.phi[i] *= aPhi[c][i];
        }
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
    for (const RootedTree<S>& tree : made) {
      trees.push_back(tree);
      aPhi.push_back(times(tree.phi));
    }
  }
  return trees;
}

// b is not deduced (std::array's size is a size_t, S an int): S comes from the tree.
template <int S>
double conditionResidual(const std::type_identity_t<std::array<double, S>>& b, const RootedTree<S>& tree) {
  double s = 0.0;
  for (int i = 0; i < S; ++i) s += b[i] * tree.phi[i];
  return s - 1.0 / tree.gamma;
}

// The largest |b . Phi(t) - 1/gamma(t)| over the trees of orders [from, to].
template <int S>
double worstResidual(const std::vector<RootedTree<S>>& trees, const std::type_identity_t<std::array<double, S>>& b,
                     int from, int to) {
  double worst = 0.0;
  for (const RootedTree<S>& t : trees)
    if (t.order >= from && t.order <= to) worst = std::max(worst, std::abs(conditionResidual(b, t)));
  return worst;
}

// A pair's table (TableauPair.h's layout) as a ButcherTableau.
template <class Table>
ButcherTableau<Table::kStages> tableauOf() {
  ButcherTableau<Table::kStages> t;
  for (int i = 0; i < Table::kStages; ++i) {
    t.c[i] = Table::c[i];
    t.b[i] = Table::b[i];
    t.bHat[i] = Table::bHat[i];
    for (int j = 0; j < Table::kStages; ++j) t.a[i][j] = Table::a[i][j];
  }
  return t;
}

// The pair's rows sum to c, b meets every condition up to kOrder and b_hat
// every one up to kOrder - 1, all within `rounding` (what the coefficients'
// digits allow); and b_hat misses order kOrder by more than `missBy`, as an
// error estimate must. Prints the worst residuals it measured.
template <class Table>
void expectPairMeetsOrderConditions(double rounding, double missBy) {
  constexpr int S = Table::kStages, p = Table::kOrder;
  const ButcherTableau<S> t = tableauOf<Table>();
  for (int i = 1; i < S; ++i) {
    double row = 0.0;
    for (int j = 0; j < i; ++j) row += t.a[i][j];
    EXPECT_NEAR(row, t.c[i], rounding) << "row " << i << " sums to c";
  }
  const auto trees = treesUpTo(t, p);
  // Rooted trees up to orders 1..9: 1, 2, 4, 8, 17, 37, 85, 200, 486 (OEIS A000081, summed).
  constexpr std::size_t kTreesUpTo[] = {0, 1, 2, 4, 8, 17, 37, 85, 200, 486};
  ASSERT_LE(p, 9);
  ASSERT_EQ(trees.size(), kTreesUpTo[p]);
  const double worstB = worstResidual(trees, t.b, 1, p), worstBHat = worstResidual(trees, t.bHat, 1, p - 1),
               missed = worstResidual(trees, t.bHat, p, p);
  std::printf("[measured] %.*s: worst residual of b to order %d %.1e, of b_hat to order %d %.1e; b_hat misses order "
              "%d by %.1e\n",
              static_cast<int>(Table::kName.size()), Table::kName.data(), p, worstB, p - 1, worstBHat, p, missed);
  EXPECT_LT(worstB, rounding);
  EXPECT_LT(worstBHat, rounding);
  EXPECT_GT(missed, missBy);
}

}  // namespace hemiroll::test
