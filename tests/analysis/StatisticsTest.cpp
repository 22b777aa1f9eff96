// engine/analysis Statistics: the small statistics every detector reports with.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
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

// Long columns are selected within a bracket from a sample (issue 32): the
// values must still be the sort's, on noise, ties, a constant, sorted and
// reversed columns, a periodic one (which a strided sample may alias) and
// infinities; and a NaN must give what a selection over all gives.
TEST(Statistics, QuantileOfALongColumnIsTheSortedDefinition) {
  std::mt19937 rng(36);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (const std::size_t n : {2047u, 2048u, 2051u, 6001u, 60001u}) {
    for (int kind = 0; kind < 7; ++kind) {
      std::vector<double> v(n);
      for (std::size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i);
        switch (kind) {
          case 0: v[i] = normal(rng); break;
          case 1: v[i] = std::round(4.0 * normal(rng)) / 4.0; break;
          case 2: v[i] = 0.25; break;
          case 3: v[i] = t; break;
          case 4: v[i] = -t; break;
          case 5: v[i] = std::sin(2.0 * 3.14159265358979 * t / 256.0) + 1e-3 * std::sin(0.37 * t); break;
          default: v[i] = i % 97 == 0 ? (i % 2 ? 1.0 : -1.0) / 0.0 : normal(rng); break;
        }
      }
      std::vector<double> sorted = v;
      std::sort(sorted.begin(), sorted.end());
      for (const double q : {0.0, 0.001, 0.05, 0.5, 0.77, 0.95, 0.999, 1.0}) {
        const double at = q * static_cast<double>(n - 1);
        const auto below = static_cast<std::size_t>(std::floor(at));
        const std::size_t above = std::min(below + 1, n - 1);
        const double w = at - static_cast<double>(below);
        const double expected = sorted[below] * (1.0 - w) + sorted[above] * w;
        const double got = quantile(v, q);
        EXPECT_TRUE(got == expected || (std::isnan(got) && std::isnan(expected))) << "n " << n << " kind " << kind << " q " << q;
      }
    }
  }
  std::vector<double> withNan(6001);
  for (double& x : withNan) x = normal(rng);
  withNan[3000] = std::nan("");
  std::vector<double> copy = withNan;  // the selection over all, as quantile made it before the bracket
  std::nth_element(copy.begin(), copy.begin() + 3000, copy.end());
  const double low = copy[3000], high = *std::min_element(copy.begin() + 3001, copy.end());
  const double expected = low * (1.0 - 0.0) + high * 0.0, got = quantile(withNan, 0.5);
  EXPECT_TRUE(std::memcmp(&got, &expected, sizeof got) == 0) << got << " against " << expected;
}

// quantiles nests its selections, or sorts a long column's sample once for
// every q (issue 32); each value must be quantile's to the bit, whatever
// the order of the qs, with ties and repeated ranks, and a NaN in the
// sample (where each q is selected over all).
TEST(Statistics, QuantilesAtOnceAreEachQuantile) {
  std::mt19937 rng(33);
  std::normal_distribution<double> normal(0.0, 1.0);
  const std::vector<std::vector<double>> qSets = {
      {0.5}, {0.05, 0.5, 0.95}, {0.95, 0.05}, {1.0, 0.0, 0.5, 0.5}, {0.3, 0.31, 0.32, 0.999, 0.001}, {}};
  for (const std::size_t n : {1u, 2u, 3u, 10u, 101u, 1000u, 6001u, 6002u}) {
    std::vector<double> v(n);
    for (double& x : v) x = std::round(8.0 * normal(rng)) / 8.0;  // coarse: many ties
    if (n > 100) v[n / 2] = 100.0;                                  // and one far out
    if (n == 6002) v[11] = std::nan("");                            // the sample's first
    for (const std::vector<double>& qs : qSets) {
      const std::vector<double> got = quantiles(v, qs);
      ASSERT_EQ(got.size(), qs.size());
      for (std::size_t i = 0; i < qs.size(); ++i) {
        // (Below 2048 the nesting may give -0 where quantile gives +0.)
        const double one = quantile(v, qs[i]);
        EXPECT_TRUE(n < 2048 ? got[i] == one : std::memcmp(&got[i], &one, sizeof one) == 0)
            << "n " << n << " q " << qs[i] << " of " << qs.size();
      }
    }
  }
  EXPECT_EQ(quantiles({}, std::vector<double>{0.5}), std::vector<double>{0.0});
}

}  // namespace
}  // namespace hemiroll::analysis
