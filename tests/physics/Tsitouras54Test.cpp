// engine/physics/Tsitouras54: the tableau typed from the paper against every
// Runge-Kutta order condition (the 17 rooted trees up to order 5 for the
// propagated weights, the 8 up to order 4 for the embedded ones), then the
// pair at work: its error tracks the tolerance, its dense output has the
// cubic Hermite's order, and it needs fewer evaluations than DOPRI5 for the
// same error.

#include "engine/physics/Tsitouras54.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "engine/physics/DormandPrince54.h"
#include "tests/physics/support/ConvergenceOrder.h"
#include "tests/physics/support/KnownSolution.h"

namespace hemiroll::test {
namespace {

using namespace physics;
constexpr int S = 7;
using Vec = std::array<double, S>;
using Mat = std::array<Vec, S>;

struct Tableau {
  Mat a{};
  Vec b{}, bHat{}, c{};
};

Tableau tableau() {
  using namespace tsit5;
  Tableau t;
  t.c = {0.0, c2, c3, c4, c5, 1.0, 1.0};
  t.a[1] = {a21};
  t.a[2] = {a31, a32};
  t.a[3] = {a41, a42, a43};
  t.a[4] = {a51, a52, a53, a54};
  t.a[5] = {a61, a62, a63, a64, a65};
  t.a[6] = {b1, b2, b3, b4, b5, b6};
  t.b = {b1, b2, b3, b4, b5, b6, 0.0};
  const Vec e = {e1, e2, e3, e4, e5, e6, e7};
  for (int i = 0; i < S; ++i) t.bHat[i] = t.b[i] - e[i];
  return t;
}

Vec mul(const Mat& a, const Vec& v) {
  Vec out{};
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < S; ++j) out[i] += a[i][j] * v[j];
  return out;
}
Vec times(const Vec& u, const Vec& v) {
  Vec out{};
  for (int i = 0; i < S; ++i) out[i] = u[i] * v[i];
  return out;
}
double dot(const Vec& u, const Vec& v) {
  double s = 0.0;
  for (int i = 0; i < S; ++i) s += u[i] * v[i];
  return s;
}

struct Condition {
  const char* tree;
  double value, exact;
};

// b . Phi(tree) = 1 / tree!, for every rooted tree of order <= `order`.
std::vector<Condition> conditions(const Tableau& t, const Vec& b, int order) {
  const Vec one = {1, 1, 1, 1, 1, 1, 1}, c = t.c, c2 = times(c, c), c3 = times(c2, c);
  const Vec ac = mul(t.a, c), ac2 = mul(t.a, c2), aac = mul(t.a, ac);
  std::vector<Condition> out = {{"1", dot(b, one), 1.0}, {"c", dot(b, c), 1.0 / 2}};
  if (order >= 3) out.insert(out.end(), {{"c^2", dot(b, c2), 1.0 / 3}, {"Ac", dot(b, ac), 1.0 / 6}});
  if (order >= 4)
    out.insert(out.end(), {{"c^3", dot(b, c3), 1.0 / 4},
                           {"c.Ac", dot(b, times(c, ac)), 1.0 / 8},
                           {"Ac^2", dot(b, ac2), 1.0 / 12},
                           {"AAc", dot(b, aac), 1.0 / 24}});
  if (order >= 5)
    out.insert(out.end(), {{"c^4", dot(b, times(c3, c)), 1.0 / 5},
                           {"c^2.Ac", dot(b, times(c2, ac)), 1.0 / 10},
                           {"Ac.Ac", dot(b, times(ac, ac)), 1.0 / 20},
                           {"c.Ac^2", dot(b, times(c, ac2)), 1.0 / 15},
                           {"c.AAc", dot(b, times(c, aac)), 1.0 / 30},
                           {"Ac^3", dot(b, mul(t.a, c3)), 1.0 / 20},
                           {"A(c.Ac)", dot(b, mul(t.a, times(c, ac))), 1.0 / 40},
                           {"AAc^2", dot(b, mul(t.a, ac2)), 1.0 / 60},
                           {"AAAc", dot(b, mul(t.a, aac)), 1.0 / 120}});
  return out;
}

TEST(Tsitouras54, TheTypedTableauMeetsEveryOrderCondition) {
  const Tableau t = tableau();
  // The coefficients are 16-17 significant digits: the conditions hold to a
  // few units in the last place of the largest products (|a| up to 13).
  constexpr double kTypedDigits = 1e-14;
  for (int i = 1; i < S; ++i) {
    double row = 0.0;
    for (int j = 0; j < i; ++j) row += t.a[i][j];
    EXPECT_NEAR(row, t.c[i], kTypedDigits) << "row " << i << " sums to c";
  }
  const auto fifth = conditions(t, t.b, 5);
  ASSERT_EQ(fifth.size(), 17u);
  for (const Condition& k : fifth) EXPECT_NEAR(k.value, k.exact, kTypedDigits) << "b, tree " << k.tree;
  const auto fourth = conditions(t, t.bHat, 4);
  ASSERT_EQ(fourth.size(), 8u);
  for (const Condition& k : fourth) EXPECT_NEAR(k.value, k.exact, kTypedDigits) << "b_hat, tree " << k.tree;
  // ... and the embedded solution is of order 4, not 5: an error estimate.
  double worst = 0.0;
  for (const Condition& k : conditions(t, t.bHat, 5)) worst = std::max(worst, std::abs(k.value - k.exact));
  EXPECT_GT(worst, 1e-4);
}

TEST(Tsitouras54, ErrorTracksToleranceWithFewerEvaluationsThanDopri5) {
  const KnownSolutionSystem f;
  const double T = 3.0;
  std::vector<double> tols, errors;
  for (double tol = 1e-4; tol >= 1e-10; tol *= 0.01) {
    double e[2] = {};
    long long evaluations[2] = {};
    for (int which = 0; which < 2; ++which) {
      std::unique_ptr<AdaptiveIntegrator<2>> m;
      if (which == 0) m = std::make_unique<Tsitouras54<2>>();
      else m = std::make_unique<DormandPrince54<2>>();
      m->setTolerance(tol);
      double t = 0.0;
      StateVector<2> x = KnownSolutionSystem::exact(0.0);
      ASSERT_TRUE(m->advanceTo(f, t, x, T));
      EXPECT_EQ(t, T);
      e[which] = (x - KnownSolutionSystem::exact(T)).cwiseAbs().maxCoeff();
      evaluations[which] = m->statistics().evaluations;
    }
    std::printf("[measured] tol %.0e: tsit5 error %.2e in %lld evaluations, dopri5 %.2e in %lld\n", tol, e[0],
                evaluations[0], e[1], evaluations[1]);
    // As for DOPRI5 (AdaptiveIntegratorTest): within 30x of tol, not 1000x below.
    EXPECT_LT(e[0], 30.0 * tol);
    // What the pair was chosen for: no more work for no more error (measured
    // here: 3-12 % fewer evaluations for 1.3-3.7x less error).
    EXPECT_LE(evaluations[0], evaluations[1]);
    EXPECT_LE(e[0], e[1]);
    EXPECT_GT(e[0], 1e-3 * tol);
    tols.push_back(tol);
    errors.push_back(e[0]);
  }
  const double slope = observedOrder(tols, errors);
  std::printf("[measured] tsit5: d log(error) / d log(tol) = %.2f\n", slope);
  EXPECT_GT(slope, 0.7);
  EXPECT_LT(slope, 1.2);
}

// Equal steps, the interpolant at the quarter points against the closed
// form: a cubic Hermite's error is h^4, so the observed order is 4.
TEST(Tsitouras54, DenseOutputIsTheCubicHermitesOrder) {
  const KnownSolutionSystem f;
  const double T = 3.0;
  std::vector<double> steps, errors;
  for (int n = 30; n <= 120; n *= 2) {
    Tsitouras54<2> m;
    const double h = T / n;
    m.start(f, 0.0, KnownSolutionSystem::exact(0.0));
    double worst = 0.0;
    for (int i = 0; i < n; ++i) {
      m.takeFixedStep(f, h);
      for (double theta : {0.0, 0.25, 0.5, 0.75, 1.0}) {
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
  std::printf("[measured] tsit5 dense output: order %.2f\n", p);
  EXPECT_GE(p, 3.7);
  EXPECT_LE(p, 4.6);
}

}  // namespace
}  // namespace hemiroll::test
