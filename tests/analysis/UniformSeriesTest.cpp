// engine/analysis UniformSeries: even resampling, NaN rows, gaps, decimation.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "engine/analysis/UniformSeries.h"

namespace hemiroll::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

UniformSeries resample(const std::vector<double>& t, const std::vector<double>& v, const ResampleDef& def = {}) {
  const std::span<const double> channels[] = {v};
  return resampleUniform(t, channels, def);
}

TEST(UniformSeries, KeepsA100HzRecordingAsItIs) {
  std::vector<double> t, v;
  for (int i = 0; i < 100; ++i) t.push_back(0.01 * (i + 1)), v.push_back(std::sin(0.1 * i));
  const UniformSeries s = resample(t, v);
  ASSERT_TRUE(s.ok()) << s.problem;
  ASSERT_EQ(s.size(), 100u);
  EXPECT_DOUBLE_EQ(s.t0, 0.01);
  // The grid falls on the samples; interpolation weights are 0 up to round-off.
  for (std::size_t i = 0; i < 100; ++i) EXPECT_NEAR(s.channels[0][i], v[i], 1e-12);
}

TEST(UniformSeries, DecimatesDenseDataToTheMaximumRate) {
  std::vector<double> t, v;
  for (int i = 0; i <= 1000; ++i) t.push_back(0.001 * i), v.push_back(2.0 * t.back());
  const UniformSeries s = resample(t, v);
  ASSERT_TRUE(s.ok());
  EXPECT_DOUBLE_EQ(s.dt, 0.01);
  EXPECT_EQ(s.size(), 101u);
  EXPECT_NEAR(s.channels[0].back(), 2.0, 1e-12);
}

TEST(UniformSeries, DropsNaNRowsAndInterpolatesAcrossShortGaps) {
  std::vector<double> t, v;
  for (int i = 0; i < 50; ++i) t.push_back(0.01 * i), v.push_back(3.0 * t.back());
  v[20] = kNaN, v[21] = kNaN;
  const UniformSeries s = resample(t, v);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.droppedRows, 2u);
  EXPECT_NEAR(s.channels[0][20], 0.6, 1e-12);  // linear data interpolates exactly
  for (double x : s.channels[0]) EXPECT_TRUE(std::isfinite(x));
}

TEST(UniformSeries, KeepsTheLongestPieceAcrossALongDropout) {
  std::vector<double> t, v;
  for (int i = 0; i < 300; ++i) t.push_back(0.01 * i), v.push_back(1.0);
  for (int i = 100; i < 150; ++i) v[i] = kNaN;  // 0.5 s without data > maxGap 0.25 s
  const UniformSeries s = resample(t, v);
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s.t0, 1.5, 1e-12);
  EXPECT_EQ(s.size(), 150u);
}

TEST(UniformSeries, SaysWhyWhenNothingUsableIsLeft) {
  const std::vector<double> t{0.0, 0.01, 0.02}, v{kNaN, kNaN, kNaN};
  EXPECT_NE(resample(t, v).problem.find("usable samples"), std::string::npos);
  EXPECT_FALSE(resample({}, {}).ok());
  const std::vector<double> shorter{1.0};
  EXPECT_NE(resample(t, shorter).problem.find("not as long"), std::string::npos);
}

}  // namespace
}  // namespace hemiroll::analysis
