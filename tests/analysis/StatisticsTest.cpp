// engine/analysis Statistics: the small statistics every detector reports with.

#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
}  // namespace hemiroll::analysis
