// engine/analysis UniformSeries: even resampling, NaN rows, gaps, decimation.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "engine/analysis/Statistics.h"
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

// resampleUniform takes all rows without a test per row where every one is
// usable, decides the spacing by a count where most lie below 1 / maxRate,
// and steps between rows without a branch (issue 32): the series must be
// the plain construction's to the bit (this is it, as it was), on 100 Hz
// rows on and off the grid, denser rows, NaN and repeated rows, gaps, and
// rates either side of the data's.
UniformSeries plainResample(std::span<const double> time, std::span<const std::span<const double>> channels,
                            const ResampleDef& def) {
  UniformSeries out;
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < time.size(); ++i) {
    bool finite = std::isfinite(time[i]);
    for (const auto& c : channels) finite = finite && std::isfinite(c[i]);
    if (!finite || (!rows.empty() && time[i] <= time[rows.back()])) {
      ++out.droppedRows;
      continue;
    }
    rows.push_back(i);
  }
  const auto minSamples = static_cast<std::size_t>(std::max(def.minSamples, 2));
  if (rows.size() < minSamples) return out.problem = "rows", out;
  std::size_t bestFirst = 0, bestLast = 0, first = 0;
  for (std::size_t k = 1; k <= rows.size(); ++k) {
    if (k == rows.size() || time[rows[k]] - time[rows[k - 1]] > def.maxGap) {
      if (time[rows[k - 1]] - time[rows[first]] > time[rows[bestLast]] - time[rows[bestFirst]])
        bestFirst = first, bestLast = k - 1;
      first = k;
    }
  }
  if (bestLast - bestFirst + 1 < minSamples) return out.problem = "piece", out;
  std::vector<double> spacing;
  for (std::size_t k = bestFirst + 1; k <= bestLast; ++k) spacing.push_back(time[rows[k]] - time[rows[k - 1]]);
  out.dt = std::max(median(spacing), 1.0 / def.maxRate);
  out.t0 = time[rows[bestFirst]];
  const double span = time[rows[bestLast]] - out.t0;
  const auto n = static_cast<std::size_t>(std::floor(span / out.dt * (1.0 + 1e-12))) + 1;
  if (n < minSamples) return out.problem = "span", out;
  out.channels.assign(channels.size(), std::vector<double>(n));
  std::size_t k = bestFirst;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = std::min(out.time(i), time[rows[bestLast]]);
    while (k + 1 < bestLast && time[rows[k + 1]] <= t) ++k;
    const std::size_t a = rows[k], b = rows[k + 1];
    const double w = std::clamp((t - time[a]) / (time[b] - time[a]), 0.0, 1.0);
    for (std::size_t c = 0; c < channels.size(); ++c) out.channels[c][i] = channels[c][a] * (1.0 - w) + channels[c][b] * w;
  }
  return out;
}

TEST(UniformSeries, HasThePlainConstructionsBits) {
  std::mt19937 rng(36);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 99);
  int compared = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const std::size_t n = 2 + static_cast<std::size_t>(trial % 113) * 13;
    const int kind = trial % 6;
    const double rate = kind == 2 ? 1000.0 : kind == 3 ? 37.0 : 100.0;
    const double start = trial % 4 == 0 ? 0.0 : 0.01 * (trial % 97);
    std::vector<double> t(n);
    for (std::size_t i = 0; i < n; ++i) {
      t[i] = kind == 0 ? static_cast<double>(i) * 0.01                            // the simulator's grid
             : kind == 1 ? start + static_cast<double>(i) * 0.01                   // off it by round-off
             : kind == 4 ? start + (static_cast<double>(i) + 0.3 * normal(rng)) / rate  // jitter, some out of order
                         : start + static_cast<double>(i) / rate;
    }
    std::vector<std::vector<double>> columns(1 + trial % 4, std::vector<double>(n));
    for (auto& column : columns)
      for (double& v : column) v = trial % 7 == 0 ? (pick(rng) < 50 ? 0.0 : -0.0) : normal(rng);
    if (kind == 5) {  // NaN, infinite and repeated rows, and a long dropout; or one of them alone
      const int only = trial / 6 % 4;
      for (std::size_t i = 0; i < n; ++i) {
        const int p = pick(rng);
        if (p == 0 && only == 0) columns[i % columns.size()][i] = std::numeric_limits<double>::quiet_NaN();
        if (p == 1 && (only == 0 || only == 2)) t[i] = std::numeric_limits<double>::infinity();
        if (p == 2 && (only == 0 || only == 3) && i > 0) t[i] = t[i - 1];
        if (p == 3 && (only == 0 || only == 1)) columns.back()[i] = -std::numeric_limits<double>::infinity();
      }
      if (only == 0)
        for (std::size_t i = n / 3; i < n / 3 + 40 && i < n; ++i) columns[0][i] = std::numeric_limits<double>::quiet_NaN();
    }
    std::vector<std::span<const double>> channels(columns.begin(), columns.end());
    for (const double maxRate : {100.0, 50.0, 250.0, 1e9}) {
      const ResampleDef def{.maxRate = maxRate};
      const UniformSeries fast = resampleUniform(t, channels, def), slow = plainResample(t, channels, def);
      ASSERT_EQ(fast.ok(), slow.ok()) << "trial " << trial << ": " << fast.problem;
      EXPECT_EQ(fast.droppedRows, slow.droppedRows) << "trial " << trial;
      if (!fast.ok()) continue;
      ++compared;
      EXPECT_EQ(std::memcmp(&fast.t0, &slow.t0, sizeof fast.t0), 0) << "trial " << trial;
      EXPECT_EQ(std::memcmp(&fast.dt, &slow.dt, sizeof fast.dt), 0) << "trial " << trial << " max rate " << maxRate;
      ASSERT_EQ(fast.channels.size(), slow.channels.size());
      for (std::size_t c = 0; c < fast.channels.size(); ++c) {
        ASSERT_EQ(fast.channels[c].size(), slow.channels[c].size()) << "trial " << trial;
        EXPECT_EQ(std::memcmp(fast.channels[c].data(), slow.channels[c].data(), sizeof(double) * fast.channels[c].size()), 0)
            << "trial " << trial << " channel " << c << " max rate " << maxRate;
      }
    }
  }
  EXPECT_GT(compared, 1500);
  // One repeated time, among the last rows (tested one by one) or the others.
  for (std::size_t n = 1000; n < 1020; ++n) {
    for (const std::size_t repeated : {n - 1, n - 9, n / 2}) {
      std::vector<double> t(n), v(n);
      for (std::size_t i = 0; i < n; ++i) t[i] = 0.01 * static_cast<double>(i), v[i] = normal(rng);
      t[repeated] = t[repeated - 1];
      const std::span<const double> channels[] = {v};
      const UniformSeries fast = resampleUniform(t, channels, {}), slow = plainResample(t, channels, {});
      EXPECT_EQ(fast.droppedRows, slow.droppedRows) << "n " << n << " repeated " << repeated;
      ASSERT_EQ(fast.size(), slow.size());
      EXPECT_EQ(std::memcmp(fast.channels[0].data(), slow.channels[0].data(), sizeof(double) * fast.size()), 0);
    }
  }
}

}  // namespace
}  // namespace hemiroll::analysis
