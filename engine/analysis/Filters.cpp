#include "engine/analysis/Filters.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hemiroll::analysis {

std::size_t halfWidthFor(double duration, double dt) {
  if (!(duration > 0.0) || !(dt > 0.0)) return 0;
  return static_cast<std::size_t>(std::lround(0.5 * duration / dt));
}

std::vector<double> movingAverage(std::span<const double> values, std::size_t halfWidth) {
  const std::size_t n = values.size();
  std::vector<double> out(n);
  // Prefix sums make every window O(1); the values are O(1) physical
  // quantities, so the cancellation in the difference is harmless.
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + values[i];
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t h = std::min({halfWidth, i, n - 1 - i});
    out[i] = (prefix[i + h + 1] - prefix[i - h]) / static_cast<double>(2 * h + 1);
  }
  return out;
}

// Each sample's slope is sum_k k (v[i+k] - v[i-k]) / (sum_k 2 k^2 dt), k = 1
// .. h, both sums in ascending k. Where the window is whole (h = halfWidth)
// the loops run k outside and i inside (in blocks of samples), so that the samples' sums advance
// side by side instead of each waiting on its own chain of additions
// (issue 32: 7 % of a sweep), and the denominator is summed once; each sum
// still takes its terms in the same order, so the slopes have the same bits.
std::vector<double> localSlope(std::span<const double> values, double dt, std::size_t halfWidth) {
  const std::size_t n = values.size();
  std::vector<double> out(n, 0.0);
  if (n < 2) return out;
  halfWidth = std::max<std::size_t>(halfWidth, 1);
  auto windowSlope = [&](std::size_t i, std::size_t h) {
    double num = 0.0, den = 0.0;
    for (std::size_t k = 1; k <= h; ++k) {
      const double kk = static_cast<double>(k);
      num += kk * (values[i + k] - values[i - k]);
      den += 2.0 * kk * kk;
    }
    return num / (den * dt);
  };
  // Whole windows: i in [halfWidth, n - halfWidth).
  const std::size_t first = std::min(halfWidth, n), last = n > halfWidth ? std::max(first, n - halfWidth) : first;
  if (last > first) {
    double den = 0.0;
    for (std::size_t k = 1; k <= halfWidth; ++k) {
      const double kk = static_cast<double>(k);
      den += 2.0 * kk * kk;
    }
    // In blocks of samples, so that a block's sums stay in the L1 cache over
    // all k (a whole column's did not: they went to L2 and back once per k).
    constexpr std::size_t kBlock = 256;
    for (std::size_t block = first; block < last; block += kBlock) {
      const std::size_t end = std::min(block + kBlock, last);
      for (std::size_t k = 1; k <= halfWidth; ++k) {
        const double kk = static_cast<double>(k);
        for (std::size_t i = block; i < end; ++i) out[i] += kk * (values[i + k] - values[i - k]);
      }
    }
    const double scale = den * dt;
    for (std::size_t i = first; i < last; ++i) out[i] /= scale;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (i >= first && i < last) continue;
    const std::size_t h = std::min({halfWidth, i, n - 1 - i});
    // An end sample: the one-sided difference to its neighbour.
    if (h == 0) out[i] = i == 0 ? (values[1] - values[0]) / dt : (values[n - 1] - values[n - 2]) / dt;
    else out[i] = windowSlope(i, h);
  }
  return out;
}

std::vector<double> unwrapAngles(std::span<const double> angles) {
  std::vector<double> out(angles.begin(), angles.end());
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double offset = 0.0;
  for (std::size_t i = 1; i < out.size(); ++i) {
    const double step = angles[i] - angles[i - 1];
    offset -= kTwoPi * std::round(step / kTwoPi);
    out[i] = angles[i] + offset;
  }
  return out;
}

}  // namespace hemiroll::analysis
