// engine/analysis Statistics: the small statistics every detector reports with.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "engine/analysis/Statistics.h"

namespace hemiroll::analysis {
namespace {

TEST(Statistics, MedianQuantileAndSpreadOfKnownValues) {
  const std::vector<double> v{4.0, 1.0, 3.0, 2.0};
  EXPECT_DOUBLE_EQ(median(v), 2.5);
  EXPECT_DOUBLE_EQ(quantile(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile(v, 1.0), 4.0);
  EXPECT_DOUBLE_EQ(quantile(v, 1.0 / 3.0), 2.0);
  EXPECT_DOUBLE_EQ(mean(v), 2.5);
  EXPECT_DOUBLE_EQ(standardDeviation(v), std::sqrt(5.0 / 3.0));  // sum of squares 5 over n - 1 = 3
  const Estimate e = summarize(v);
  EXPECT_EQ(e.count, 4);
  EXPECT_DOUBLE_EQ(e.value, 2.5);
}

TEST(Statistics, EmptyAndSingleValuesGiveZeroNotNaN) {
  const std::vector<double> none, one{7.0};
  EXPECT_EQ(median(none), 0.0);
  EXPECT_EQ(mean(none), 0.0);
  EXPECT_EQ(standardDeviation(one), 0.0);
  EXPECT_EQ(summarize(none).count, 0);
}

// quantile selects its two order statistics instead of sorting: the result
// must be the sorted definition's to the bit, ties and odd sizes included.
TEST(Statistics, QuantileBySelectionIsTheSortedDefinition) {
  std::mt19937 rng(32);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (const std::size_t n : {1u, 2u, 3u, 10u, 101u, 1000u}) {
    std::vector<double> v(n);
    for (double& x : v) x = std::round(8.0 * normal(rng)) / 8.0;  // coarse: many ties
    std::vector<double> sorted = v;
    std::sort(sorted.begin(), sorted.end());
    for (const double q : {0.0, 0.05, 0.25, 1.0 / 3.0, 0.5, 0.77, 0.95, 1.0}) {
      const double at = q * static_cast<double>(n - 1);
      const auto below = static_cast<std::size_t>(std::floor(at));
      const std::size_t above = std::min(below + 1, n - 1);
      const double w = at - static_cast<double>(below);
      const double expected = sorted[below] * (1.0 - w) + sorted[above] * w;
      EXPECT_EQ(quantile(v, q), expected) << "n " << n << " q " << q;
    }
  }
}

// quantiles nests its selections (issue 32); each value must be quantile's
// to the bit, whatever the order of the qs, with ties and repeated ranks.
TEST(Statistics, QuantilesAtOnceAreEachQuantile) {
  std::mt19937 rng(33);
  std::normal_distribution<double> normal(0.0, 1.0);
  const std::vector<std::vector<double>> qSets = {
      {0.5}, {0.05, 0.5, 0.95}, {0.95, 0.05}, {1.0, 0.0, 0.5, 0.5}, {0.3, 0.31, 0.32, 0.999, 0.001}, {}};
  for (const std::size_t n : {1u, 2u, 3u, 10u, 101u, 1000u, 6001u}) {
    std::vector<double> v(n);
    for (double& x : v) x = std::round(8.0 * normal(rng)) / 8.0;  // coarse: many ties
    if (n > 100) v[n / 2] = 100.0;                                  // and one far out
    for (const std::vector<double>& qs : qSets) {
      const std::vector<double> got = quantiles(v, qs);
      ASSERT_EQ(got.size(), qs.size());
      for (std::size_t i = 0; i < qs.size(); ++i)
        EXPECT_EQ(got[i], quantile(v, qs[i])) << "n " << n << " q " << qs[i] << " of " << qs.size();
    }
  }
  EXPECT_EQ(quantiles({}, std::vector<double>{0.5}), std::vector<double>{0.0});
}

}  // namespace
}  // namespace hemiroll::analysis
